#include "sim_profile.hpp"

#include <string>

#include "sandflow/sim/estimate.hpp"
#include "sandflow/tcl/args.hpp"

namespace sf::tcl {
namespace {

// The most steps an estimate takes: past it, a run would take years.
constexpr Tcl_WideInt kMaxEstimateSteps = 1'000'000'000;
constexpr Tcl_WideInt kDefaultEstimateSteps = 100;

}  // namespace

Tcl_Obj* passesDict(const Session& s) {
  const Profile& p = s.running ? s.manager.profile() : s.lastRun.profile;
  Tcl_Obj* dict = Tcl_NewDictObj();
  for (int k = 0; k < kStageCount; ++k) {
    const StageTime& t = p[Stage(k)];
    if (t.steps == 0) continue;
    const std::string name(stageName(Stage(k)));
    Tcl_DictObjPut(nullptr, dict, newString(name),
                   newDict({{"seconds", newDouble(t.seconds)},
                            {"steps", Tcl_NewWideIntObj(t.steps)},
                            {"perstep", newDouble(t.seconds / double(t.steps))}}));
  }
  return dict;
}

int SimEstimate(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc > 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "?N?");
    return TCL_ERROR;
  }
  Tcl_WideInt steps = kDefaultEstimateSteps;
  if (objc == 2 && (Tcl_GetWideIntFromObj(nullptr, objv[1], &steps) != TCL_OK || steps < 1 ||
                    steps > kMaxEstimateSteps))
    return fail(interp, "VALUE STEPS",
                "N must be a whole number from 1 to " + std::to_string(kMaxEstimateSteps) +
                    ", got \"" + Tcl_GetString(objv[1]) + "\"");
  const Session& s = sessionOf(data);
  return guarded(interp, [&] {
    const sim::Estimate e = sim::estimate(s.manager, steps, &s.lastRun);
    Tcl_Obj* passes = Tcl_NewDictObj();
    for (int k = 0; k < kStageCount; ++k)
      if (e.ran[k])
        Tcl_DictObjPut(nullptr, passes, newString(std::string(stageName(Stage(k)))),
                       newDouble(e.stages[k]));
    Tcl_SetObjResult(interp, newDict({{"steps", Tcl_NewWideIntObj(e.steps)},
                                      {"seconds", newDouble(e.seconds)},
                                      {"perstep", newDouble(e.seconds / double(e.steps))},
                                      {"basis", newString(e.trial ? "trial" : "run")},
                                      {"basissteps", Tcl_NewWideIntObj(e.basisSteps)},
                                      {"passes", passes}}));
    return TCL_OK;
  });
}

}  // namespace sf::tcl
