// source create|delete|ids|info|options|help
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/option_table.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

// What source create takes, converted and checked before the kernel sees it.
struct SourceDraft {
  Vec2 acceleration = Vec2::Zero();
  double interval = 0;
  int limit = -1;
};

using Row = Option<SourceDraft>;
const OptionTable<SourceDraft> kOptions{
    Row{.info = {.name = "-acceleration",
                 .synopsis = "{ax ay}",
                 .help = "body acceleration of each clone",
                 .kind = ValueKind::vec2,
                 .unit = "length/time^2"},
        .get = [](const SourceDraft& s) { return vecValue(s.acceleration); },
        .set = [](SourceDraft& s, const OptionValue& v) { s.acceleration = v.vec; }},
    Row{.info = {.name = "-interval",
                 .synopsis = "t",
                 .help = "least time between two clones",
                 .unit = "time",
                 .range = {.min = 0}},
        .get = [](const SourceDraft& s) { return realValue(s.interval); },
        .set = [](SourceDraft& s, const OptionValue& v) { s.interval = v.real; }},
    Row{.info = {.name = "-limit",
                 .synopsis = "n",
                 .help = "clones to make; -1 for no limit",
                 .kind = ValueKind::integer,
                 .range = {.min = -1}},
        .get = [](const SourceDraft& s) { return integerValue(s.limit); },
        .set = [](SourceDraft& s, const OptionValue& v) { s.limit = v.integer; }},
};

int SourceCreate(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc < 2 || objc % 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "ID ?-acceleration {ax ay}? ?-interval t? ?-limit n?");
    return TCL_ERROR;
  }
  int id = 0;
  SourceDraft draft;
  if (!getInt(interp, objv[1], "ID", id)) return TCL_ERROR;
  if (!kOptions.apply(interp, objc, objv, 2, draft)) return TCL_ERROR;
  return guarded(interp, [&] {
    sessionOf(data).manager.assembly().makeSource(id, draft.acceleration, draft.interval,
                                                  draft.limit);
    Tcl_SetObjResult(interp, Tcl_NewIntObj(id));
    return TCL_OK;
  });
}

int SourceDelete(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  int id = 0;
  if (!getSoleId(interp, objc, objv, "ID", id)) return TCL_ERROR;
  return guarded(interp, [&] {
    sessionOf(data).manager.assembly().removeSource(id);
    return TCL_OK;
  });
}

int SourceIds(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  Tcl_Obj* l = Tcl_NewListObj(0, nullptr);
  for (const dem::Source& s : sessionOf(data).manager.assembly().sources())
    Tcl_ListObjAppendElement(nullptr, l, Tcl_NewIntObj(s.id));
  Tcl_SetObjResult(interp, l);
  return TCL_OK;
}

int SourceInfo(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  int id = 0;
  if (!getSoleId(interp, objc, objv, "ID", id)) return TCL_ERROR;
  for (const dem::Source& s : sessionOf(data).manager.assembly().sources()) {
    if (s.id != id) continue;
    Tcl_Obj* clones = Tcl_NewListObj(0, nullptr);
    for (int c : s.clones) Tcl_ListObjAppendElement(nullptr, clones, Tcl_NewIntObj(c));
    Tcl_SetObjResult(interp, newDict({{"id", Tcl_NewIntObj(s.id)},
                                      {"acceleration", newVec2(s.acceleration)},
                                      {"interval", newDouble(s.interval)},
                                      {"limit", Tcl_NewIntObj(s.limit)},
                                      {"made", Tcl_NewIntObj(s.made)},
                                      {"clones", clones}}));
    return TCL_OK;
  }
  return fail(interp, "LOOKUP SOURCE", "element " + std::to_string(id) + " is not a source");
}

}  // namespace

void registerSourceCommands(Tcl_Interp* interp, Session* session) {
  makeEnsemble(interp, "::sf::source",
               {{"create", SourceCreate},
                {"delete", SourceDelete},
                {"ids", SourceIds},
                {"info", SourceInfo}},
               session,
               kOptions.answers("source",
                                {"create ID ?-acceleration {ax ay}? ?-interval t? ?-limit "
                                 "n?   (element ID becomes a source)",
                                 "delete ID", "ids", "info ID   -> dict ... made clones",
                                 "options   -> create's options as dicts", "help"},
                                SourceDraft{}));
}

}  // namespace sf::tcl
