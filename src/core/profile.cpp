#include "sandflow/core/profile.hpp"

namespace sf {

std::string_view stageName(Stage stage) {
  static constexpr std::string_view kNames[kStageCount] = {
      "latticebulk",  "latticecovered", "latticefill",  "coveragemeasure",
      "coveragesort", "coveragecells",  "fluidforces",  "dempairs",
      "demcontacts",  "demsums",        "demintegrate", "outputs",
      "pictures",     "scripts",        "tick",         "other"};
  return kNames[int(stage)];
}

double Profile::totalSeconds() const {
  double sum = 0;
  for (const StageTime& t : stages_) sum += t.seconds;
  return sum;
}

}  // namespace sf
