// checkpoint save FILE, checkpoint load FILE ?-recordings 0|1?: the whole
// scene in one file (io/checkpoint.hpp), with the session's view settings and
// recordings beside the kernel's state.
#include <cstring>
#include <vector>

#include "sandflow/io/checkpoint.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/option_table.hpp"
#include "sandflow/tcl/picture.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

// What checkpoint load is asked, besides the file.
struct LoadDraft {
  bool recordings = true;
};
const OptionTable<LoadDraft> kLoadOptions{
    memberRow({.name = "-recordings",
               .synopsis = "0|1",
               .help = "start the checkpoint's recordings again"},
              &LoadDraft::recordings),
};

// The session's part: {view {-field ...} recordings {{kind path command} ...}}.
std::string sessionText(const Session& s) {
  Tcl_Obj* recordings = Tcl_NewListObj(0, nullptr);
  for (const auto& r : s.recorders) {
    Tcl_Obj* item[3] = {newString(r->kind()), newString(r->path()), newString(r->command())};
    Tcl_ListObjAppendElement(nullptr, recordings, Tcl_NewListObj(3, item));
  }
  Tcl_Obj* dict =
      newDict({{"view", viewOptionList(s.view, offscreenChoice())}, {"recordings", recordings}});
  Tcl_IncrRefCount(dict);
  std::string text = Tcl_GetString(dict);
  Tcl_DecrRefCount(dict);
  return text;
}

int CheckpointSave(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "FILE");
    return TCL_ERROR;
  }
  Session& s = sessionOf(data);
  const std::string path = Tcl_GetString(objv[1]);
  if (recording(s, path))
    return fail(interp, "VALUE OUTPUT", "\"" + path + "\" is being recorded to");
  return guarded(interp, [&] {
    requireConfined(s, path);
    io::saveCheckpoint(path, s.manager, sessionText(s));
    Tcl_SetObjResult(interp, objv[1]);
    return TCL_OK;
  });
}

// The view settings of a checkpoint, checked before anything changes.
bool stagedView(Tcl_Interp* interp, Tcl_Obj* session, render::ViewOptions& view) {
  Tcl_Obj* list = nullptr;
  Tcl_Obj** items = nullptr;
  int n = 0;
  if (Tcl_DictObjGet(interp, session, Tcl_NewStringObj("view", -1), &list) != TCL_OK || !list ||
      Tcl_ListObjGetElements(interp, list, &n, &items) != TCL_OK)
    return reject(interp, "FORMAT CHECKPOINT", "the checkpoint's view settings are unreadable");
  std::string offscreen = offscreenChoice();  // the process keeps its own back end
  std::vector<Tcl_Obj*> objv(items, items + n);
  objv.insert(objv.begin(), Tcl_NewStringObj("view", -1));
  Tcl_IncrRefCount(objv.front());
  const bool ok = parseViewOptions(interp, int(objv.size()), objv.data(), 1, view, &offscreen);
  Tcl_DecrRefCount(objv.front());
  if (!ok) Tcl_AddErrorInfo(interp, "\n    (in the checkpoint's view settings)");
  return ok;
}

// Runs a checkpoint's recording command, which must be one that startRecorder
// keeps (`output csv ...` or `record ...`): a file must not make
// `checkpoint load` run any other command. Its words are run as they are,
// without substitution. Returns "" or why it did not start.
std::string restartRecording(Tcl_Interp* interp, Tcl_Obj* command) {
  Tcl_Obj** words = nullptr;
  int n = 0;
  if (Tcl_ListObjGetElements(nullptr, command, &n, &words) != TCL_OK || n < 2)
    return "not a recording's command";
  // (as startRecorder names them: `record` is kept as imported, ::record)
  const std::string noun = Tcl_GetString(words[0]);
  const bool record = noun == "::sf::record" || noun == "::record";
  const bool csv = (noun == "::sf::output" || noun == "::output") &&
                   std::strcmp(Tcl_GetString(words[1]), "csv") == 0;
  if (!record && !csv) return "not a recording's command";
  // (the words outlive a change of the command's representation)
  std::vector<Tcl_Obj*> held(words, words + n);
  for (Tcl_Obj* w : held) Tcl_IncrRefCount(w);
  const int code = Tcl_EvalObjv(interp, n, held.data(), TCL_EVAL_GLOBAL);
  for (Tcl_Obj* w : held) Tcl_DecrRefCount(w);
  return code == TCL_OK ? "" : Tcl_GetStringResult(interp);
}

// Starts the checkpoint's recordings again: CSV series continue their files;
// the others are listed as not restarted, with the reason.
Tcl_Obj* restartRecordings(Session& s, Tcl_Obj* session, bool restart) {
  Tcl_Obj* started = Tcl_NewListObj(0, nullptr);
  Tcl_Obj* skipped = Tcl_NewListObj(0, nullptr);
  Tcl_Obj* list = nullptr;
  Tcl_Obj** items = nullptr;
  int n = 0;
  if (Tcl_DictObjGet(nullptr, session, Tcl_NewStringObj("recordings", -1), &list) != TCL_OK ||
      !list || Tcl_ListObjGetElements(nullptr, list, &n, &items) != TCL_OK)
    n = 0;
  s.resumeStep = s.manager.stepCount();
  for (int k = 0; k < n; ++k) {
    Tcl_Obj** fields = nullptr;
    int m = 0;
    if (Tcl_ListObjGetElements(nullptr, items[k], &m, &fields) != TCL_OK || m != 3) continue;
    const std::string kind = Tcl_GetString(fields[0]);
    std::string why;
    if (!restart) {
      why = "-recordings 0";
    } else if (kind != "csv" && kind != "record") {
      why = "a " + kind + " recording cannot continue its file";
    } else {
      why = restartRecording(s.interp, fields[2]);
    }
    Tcl_Obj* item[2] = {fields[1], why.empty() ? fields[2] : newString(why)};
    Tcl_ListObjAppendElement(nullptr, why.empty() ? started : skipped, Tcl_NewListObj(2, item));
  }
  s.resumeStep = -1;
  Tcl_ResetResult(s.interp);
  return newDict({{"restarted", started}, {"notrestarted", skipped}});
}

int CheckpointLoad(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc < 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "FILE ?-recordings 0|1?");
    return TCL_ERROR;
  }
  Session& s = sessionOf(data);
  if (refuseWhileRunning(s) != TCL_OK) return TCL_ERROR;
  LoadDraft load;
  if (!kLoadOptions.apply(interp, objc, objv, 2, load)) return TCL_ERROR;
  const bool restart = load.recordings;
  const std::string path = Tcl_GetString(objv[1]);
  io::Checkpoint c;
  if (guarded(interp, [&] {
        requireConfined(s, path);
        c = io::loadCheckpoint(path, s.manager.threads());
        return TCL_OK;
      }) != TCL_OK)
    return TCL_ERROR;
  Tcl_Obj* session = Tcl_NewStringObj(c.session.data(), int(c.session.size()));
  Tcl_IncrRefCount(session);
  render::ViewOptions view;
  if (!stagedView(interp, session, view)) {
    Tcl_DecrRefCount(session);
    Tcl_AppendResult(interp, " (checkpoint \"", path.c_str(), "\")", nullptr);
    return TCL_ERROR;
  }
  // The scene is replaced whole, as by reset: the old scene's output ends
  // (a file that fails to close is reported, and the load goes on).
  if (closeRecorders(s, nullptr) != TCL_OK) warnUser(s, Tcl_GetStringResult(interp));
  s.manager = std::move(*c.manager);
  s.mlups = 0.0;
  s.view = std::move(view);
  s.viewList.reset();
  Tcl_Obj* recordings = restartRecordings(s, session, restart);
  Tcl_DecrRefCount(session);
  Tcl_SetObjResult(interp, newDict({{"file", objv[1]},
                                    {"version", Tcl_NewIntObj(c.version)},
                                    {"bytes", Tcl_NewWideIntObj(c.bytes)},
                                    {"step", Tcl_NewWideIntObj(s.manager.stepCount())},
                                    {"time", newDouble(s.manager.time())},
                                    {"recordings", recordings}}));
  return TCL_OK;
}

}  // namespace

void registerCheckpointCommands(Tcl_Interp* interp, Session* session) {
  makeEnsemble(interp, "::sf::checkpoint", {{"save", CheckpointSave}, {"load", CheckpointLoad}},
               session, kLoadOptions.answers("checkpoint", {"save FILE", "load FILE"}, {}, false));
}

}  // namespace sf::tcl
