#pragma once
// How long the next steps of a scene will take (sim estimate): from the
// stages of the last run when the scene still has its size, else from trial
// steps on a copy of the scene, which is left as it was (docs/performance.md).
#include <array>
#include <cstddef>

#include "sandflow/core/profile.hpp"
#include "sandflow/sim/manager.hpp"

namespace sf::sim {

// The size of what a step works on, which its cost follows.
struct SceneSize {
  std::size_t nodes = 0, covered = 0;
  int elements = 0, threads = 1, substeps = 1;
};
SceneSize sceneSize(const Manager& m);
// Whether steps on `before` tell the cost of steps on `now`: the same lattice,
// threads and substeps; elements within 10% and covered cells within 25%.
bool sameCost(const SceneSize& before, const SceneSize& now);

// A run's stages, with Stage::other its wall time outside them, and the scene
// at its end.
struct RunRecord {
  Profile profile;
  SceneSize scene;
  double seconds = 0;  // wall time
  long long steps = 0;
};
// Ends a run that started with m.profile().reset(): its stages, the rest of
// `seconds` as Stage::other, the scene now.
RunRecord recordRun(const Manager& m, double seconds, long long steps);

struct Estimate {
  long long steps = 0;
  double seconds = 0;                        // all of it
  std::array<double, kStageCount> stages{};  // per stage, seconds
  std::array<bool, kStageCount> ran{};       // the stages the basis saw run
  bool trial = false;                        // basis: trial steps (else the last run)
  long long basisSteps = 0;                  // steps the basis measured
};
// Trial steps: at least kTrialMin after one to warm up, until kTrialSeconds
// have passed or kTrialMax were taken.
inline constexpr int kTrialMin = 3, kTrialMax = 200;
inline constexpr double kTrialSeconds = 0.5;
// Predicts `steps` steps of `m`. `lastRun` (may be null) is used when it ran a
// step and sameCost holds, else trial steps run on a copy of `m` (its state
// saved and loaded), which stays untouched. Throws the trial's sf::Error when
// a step fails.
Estimate estimate(const Manager& m, long long steps, const RunRecord* lastRun);

}  // namespace sf::sim
