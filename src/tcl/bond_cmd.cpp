// bond create|auto|ids|info|delete|broken|options|help
#include <cmath>
#include <limits>

#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/option_table.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

// What bond create sets; NaN: from the two elements' materials.
struct BondDraft {
  double stiffness = std::numeric_limits<double>::quiet_NaN();
  double strength = std::numeric_limits<double>::quiet_NaN();
  double shearStrength = std::numeric_limits<double>::quiet_NaN();
};

using Row = Option<BondDraft>;
Row bondRow(OptionInfo info, double BondDraft::*field) {
  info.range = {.min = 0};
  return memberRow(info, field);
}
const OptionTable<BondDraft> kCreateOptions{
    bondRow({.name = "-stiffness",
             .synopsis = "k",
             .help = "bond stiffness",
             .unit = "force/length",
             .defaultText = "the materials' -bondstiffness, the smaller"},
            &BondDraft::stiffness),
    bondRow({.name = "-strength",
             .synopsis = "s",
             .help = "tensile strength",
             .unit = "force",
             .defaultText = "the materials' -bondstrength, the smaller"},
            &BondDraft::strength),
    bondRow({.name = "-shearstrength",
             .synopsis = "s",
             .help = "shear strength",
             .unit = "force",
             .defaultText = "the tensile strength"},
            &BondDraft::shearStrength),
};
// What bond auto is asked: the elements (empty: all) and the gap.
struct AutoDraft {
  std::vector<int> ids;
  double gap = 0;
};
const OptionTable<AutoDraft> kAutoOptions{
    parsedRow<AutoDraft>({.name = "-elements",
                          .synopsis = "IDS",
                          .help = "only among these elements",
                          .defaultText = "all"},
                         [](Tcl_Interp* interp, Tcl_Obj* v, AutoDraft& d) {
                           return getElementIds(interp, v, d.ids);
                         }),
    memberRow({.name = "-gap",
               .synopsis = "g",
               .help = "largest surface gap bonded",
               .unit = "length",
               .range = {.min = 0}},
              &AutoDraft::gap),
};
// What bond broken is asked: the breaks since a time (all by default).
struct BrokenDraft {
  double since = -std::numeric_limits<double>::infinity();
};
const OptionTable<BrokenDraft> kBrokenOptions{
    memberRow({.name = "-since",
               .synopsis = "t",
               .help = "only breaks at or after time t",
               .unit = "time",
               .defaultText = "all"},
              &BrokenDraft::since),
};

int BondCreate(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc < 3 || objc % 2 == 0) {
    Tcl_WrongNumArgs(interp, 1, objv, "ID1 ID2 ?-stiffness k? ?-strength s? ?-shearstrength s?");
    return TCL_ERROR;
  }
  int a = 0, b = 0;
  if (!getInt(interp, objv[1], "ID1", a) || !getInt(interp, objv[2], "ID2", b)) return TCL_ERROR;
  BondDraft draft;
  if (!kCreateOptions.apply(interp, objc, objv, 3, draft)) return TCL_ERROR;
  auto orFromMaterials = [](double v) { return std::isnan(v) ? -1.0 : v; };
  return guarded(interp, [&] {
    Tcl_SetObjResult(interp,
                     Tcl_NewIntObj(sessionOf(data).manager.assembly().bond(
                         a, b, orFromMaterials(draft.stiffness), orFromMaterials(draft.strength),
                         orFromMaterials(draft.shearStrength))));
    return TCL_OK;
  });
}

int BondAuto(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc % 2 == 0) {
    Tcl_WrongNumArgs(interp, 1, objv, "?-elements IDS? ?-gap g?");
    return TCL_ERROR;
  }
  AutoDraft draft;
  if (!kAutoOptions.apply(interp, objc, objv, 1, draft)) return TCL_ERROR;
  return guarded(interp, [&] {
    Tcl_SetObjResult(
        interp, Tcl_NewIntObj(sessionOf(data).manager.assembly().bondAll(draft.ids, draft.gap)));
    return TCL_OK;
  });
}

int BondIds(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  Tcl_Obj* l = Tcl_NewListObj(0, nullptr);
  for (const dem::Bond& b : sessionOf(data).manager.assembly().bonds())
    Tcl_ListObjAppendElement(nullptr, l, Tcl_NewIntObj(b.id));
  Tcl_SetObjResult(interp, l);
  return TCL_OK;
}

int BondInfo(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  int id = 0;
  if (!getSoleId(interp, objc, objv, "BID", id)) return TCL_ERROR;
  return guarded(interp, [&] {
    const dem::Bond& b = sessionOf(data).manager.assembly().bondInfo(id);
    Tcl_Obj* ids[2] = {Tcl_NewIntObj(b.idA), Tcl_NewIntObj(b.idB)};
    Tcl_SetObjResult(interp, newDict({{"id", Tcl_NewIntObj(b.id)},
                                      {"elements", Tcl_NewListObj(2, ids)},
                                      {"force", newVec2(b.force)},
                                      {"stiffness", newDouble(b.stiffness)},
                                      {"strength", newDouble(b.strength)},
                                      {"shearstrength", newDouble(b.shearStrength)},
                                      {"length", newDouble(b.length)}}));
    return TCL_OK;
  });
}

int BondDelete(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  int id = 0;
  if (!getSoleId(interp, objc, objv, "BID", id)) return TCL_ERROR;
  return guarded(interp, [&] {
    sessionOf(data).manager.assembly().unbond(id);
    return TCL_OK;
  });
}

int BondBroken(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1 && objc != 3) {
    Tcl_WrongNumArgs(interp, 1, objv, "?-since t?");
    return TCL_ERROR;
  }
  BrokenDraft draft;
  if (!kBrokenOptions.apply(interp, objc, objv, 1, draft)) return TCL_ERROR;
  const double since = draft.since;
  Tcl_Obj* l = Tcl_NewListObj(0, nullptr);
  for (const dem::BondBreak& e : sessionOf(data).manager.assembly().breaks()) {
    if (e.time < since) continue;
    Tcl_Obj* item[4] = {newDouble(e.time), newDouble(e.at.x()), newDouble(e.at.y()),
                        newDouble(e.angle)};
    Tcl_ListObjAppendElement(nullptr, l, Tcl_NewListObj(4, item));
  }
  Tcl_SetObjResult(interp, l);
  return TCL_OK;
}

}  // namespace

void registerBondCommands(Tcl_Interp* interp, Session* session) {
  makeEnsemble(interp, "::sf::bond",
               {{"create", BondCreate},
                {"auto", BondAuto},
                {"ids", BondIds},
                {"info", BondInfo},
                {"delete", BondDelete},
                {"broken", BondBroken}},
               session,
               kCreateOptions.answers(
                   "bond",
                   {"create ID1 ID2 ?-stiffness k? ?-strength s? ?-shearstrength s?   -> bond id",
                    "auto ?-elements IDS? ?-gap g?   -> number of bonds made", "ids", "info BID",
                    "delete BID", "broken ?-since t?   -> list of {time x y angle} break events",
                    "options   -> create's options as dicts", "help"},
                   BondDraft{}));
}

}  // namespace sf::tcl
