// source create|delete|ids|info|help
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

const OptionSpec kOptions[] = {
    {"-acceleration", "{ax ay}", "body acceleration of each clone (default {0 0})"},
    {"-interval", "t", "least time between two clones (default 0)"},
    {"-limit", "n", "clones to make; -1 for no limit (default -1)"},
    {nullptr, nullptr, nullptr}};

int SourceCreate(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc < 2 || objc % 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "ID ?-acceleration {ax ay}? ?-interval t? ?-limit n?");
    return TCL_ERROR;
  }
  int id = 0, limit = -1;
  double interval = 0;
  Vec2 accel = Vec2::Zero();
  if (!getInt(interp, objv[1], "ID", id)) return TCL_ERROR;
  if (!parseOptions(interp, objc, objv, 2, kOptions, [&](int k, Tcl_Obj* v) {
        if (k == 0) return getVec2(interp, v, "-acceleration", accel);
        if (k == 1) {
          if (!getDouble(interp, v, "-interval", interval)) return false;
          if (interval < 0)
            return reject(interp, "VALUE INTERVAL",
                          "-interval must be >= 0, got " + formatNumber(interval));
          return true;
        }
        if (!getInt(interp, v, "-limit", limit)) return false;
        if (limit < -1)
          return reject(interp, "VALUE LIMIT",
                        "-limit must be >= -1, got " + std::to_string(limit));
        return true;
      }))
    return TCL_ERROR;
  return guarded(interp, [&] {
    sessionOf(data).manager.assembly().makeSource(id, accel, interval, limit);
    Tcl_SetObjResult(interp, Tcl_NewIntObj(id));
    return TCL_OK;
  });
}

bool getSourceId(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], int& id) {
  if (objc != 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "ID");
    return false;
  }
  return getInt(interp, objv[1], "ID", id);
}

int SourceDelete(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  int id = 0;
  if (!getSourceId(interp, objc, objv, id)) return TCL_ERROR;
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
  if (!getSourceId(interp, objc, objv, id)) return TCL_ERROR;
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

int SourceHelp(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  Tcl_SetObjResult(
      interp, newString(helpText("source",
                                 {"create ID ?-acceleration {ax ay}? ?-interval t? ?-limit n?   "
                                  "(element ID becomes a source)",
                                  "delete ID", "ids", "info ID   -> dict ... made clones", "help"},
                                 kOptions)));
  return TCL_OK;
}

}  // namespace

void registerSourceCommands(Tcl_Interp* interp, Session* session) {
  makeEnsemble(interp, "::sf::source",
               {{"create", SourceCreate},
                {"delete", SourceDelete},
                {"ids", SourceIds},
                {"info", SourceInfo},
                {"help", SourceHelp}},
               session);
}

}  // namespace sf::tcl
