// The recorders of a session: called after steps, finished on close, reset and exit.
#include <algorithm>
#include <filesystem>
#include <vector>

#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

int recorderError(Tcl_Interp* interp, const Recorder& r, const Error& e) {
  return fail(
      interp,
      Error(e.code(), std::string(r.kind()) + " output " + r.path() + ": " + e.what(), e.remedy()));
}

// A record as an sf::Error whatever went wrong (a frame too large for memory
// must not escape through Tcl's C frames).
template <class Body>
void asError(Body&& body) {
  try {
    body();
  } catch (const Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw Error("RESOURCE MEMORY", "out of memory");
  } catch (const std::exception& e) {
    throw Error("INTERNAL", e.what());
  }
}

void finishQuietly(Recorder& r) {
  try {
    asError([&] { r.finish(); });
  } catch (const Error&) {
    // Nothing to report to at this point; the file is as complete as it got.
  }
}

}  // namespace

std::string Recorder::samePath(const std::string& path) {
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(path, error);
  return (error ? std::filesystem::path(path) : absolute).lexically_normal().string();
}

Session::~Session() {
  for (auto& r : recorders) finishQuietly(*r);
  if (runTick) Tcl_DecrRefCount(runTick);
  if (runSample) Tcl_DecrRefCount(runSample);
}

bool recording(const Session& s, const std::string& path) {
  return std::any_of(s.recorders.begin(), s.recorders.end(),
                     [&](const auto& r) { return r->writes(path); });
}

int recordStep(Session& s) {
  const long long step = s.manager.stepCount();
  // One recorder failing does not cost the others this step's record; the
  // first failure is the Tcl error.
  int code = TCL_OK;
  const auto t0 = Profile::Clock::now();
  bool due = false;  // timed (Stage::outputs) only in the steps that record
  for (std::size_t k = 0; k < s.recorders.size();) {
    Recorder& r = *s.recorders[k];
    if (step % r.every() != 0) {
      ++k;
      continue;
    }
    due = true;
    try {
      asError([&] { r.record(s); });
      ++k;
    } catch (const Error& e) {
      if (code == TCL_OK) code = recorderError(s.interp, r, e);
      finishQuietly(r);  // what was recorded so far stays
      s.recorders.erase(s.recorders.begin() + std::ptrdiff_t(k));
    }
  }
  if (due) s.manager.profile().lap(Stage::outputs, t0);
  return code;
}

int closeRecorders(Session& s, const std::string* path) {
  if (path && !recording(s, *path))
    return fail(s.interp, "LOOKUP OUTPUT", "no output is being recorded to \"" + *path + "\"");
  int code = TCL_OK;
  for (auto it = s.recorders.begin(); it != s.recorders.end();) {
    if (path && !(*it)->writes(*path)) {
      ++it;
      continue;
    }
    try {
      asError([&] { (*it)->finish(); });
    } catch (const Error& e) {
      if (code == TCL_OK) code = recorderError(s.interp, **it, e);
    }
    it = s.recorders.erase(it);
  }
  return code;
}

int startRecorder(Session& s, std::unique_ptr<Recorder> recorder) {
  if (guarded(s.interp, [&] {
        requireConfined(s, recorder->path());
        return TCL_OK;
      }) != TCL_OK)
    return TCL_ERROR;
  if (recording(s, recorder->path()))
    return fail(s.interp, "VALUE OUTPUT",
                "\"" + recorder->path() + "\" is already being recorded to; output close it first");
  try {
    asError([&] { recorder->record(s); });
  } catch (const Error& e) {
    const int code = recorderError(s.interp, *recorder, e);
    recorder->abandon();  // nothing recorded: no file is left
    return code;
  }
  s.recorders.push_back(std::move(recorder));
  return TCL_OK;
}

int startRecorder(Session& s, std::unique_ptr<Recorder> recorder, int objc, Tcl_Obj* const objv[]) {
  // Named as a user types it, fully qualified: an ensemble's verb arrives as
  // its implementation (::sf::output::csv), which becomes "::sf::output csv".
  std::vector<Tcl_Obj*> words(objv, objv + objc);
  if (Tcl_Command token = Tcl_GetCommandFromObj(s.interp, objv[0])) {
    Tcl_Obj* full = Tcl_NewObj();
    Tcl_GetCommandFullName(s.interp, token, full);
    std::string name = Tcl_GetString(full);
    Tcl_DecrRefCount(full);
    const std::size_t verb = name.rfind("::");
    if (name.rfind("::sf::", 0) == 0 && verb > 4) {  // ::sf::NOUN::VERB
      words[0] = Tcl_NewStringObj(name.substr(0, verb).c_str(), -1);
      words.insert(words.begin() + 1, Tcl_NewStringObj(name.c_str() + verb + 2, -1));
    } else {
      words[0] = Tcl_NewStringObj(name.c_str(), -1);
    }
  }
  Tcl_Obj* command = Tcl_NewListObj(int(words.size()), words.data());
  Tcl_IncrRefCount(command);
  recorder->setCommand(Tcl_GetString(command));
  Tcl_DecrRefCount(command);
  return startRecorder(s, std::move(recorder));
}

}  // namespace sf::tcl
