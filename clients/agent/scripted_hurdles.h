// The scripted baseline for the hurdles: a walker (StepController) that walks straight down the
// middle of its lane toward the finish and through the hurdles, pushing them over (legal under
// official rules: TR 22.6), so that a run finishes. Under the seed's rules (fixed walls, a touch
// ends the run) it stops at the first hurdle: it is a floor, not a hurdler. It reads only the
// observation, by name: the goal (the finish line's point on its lane's centre) and the first
// hurdle, which give it its lane's centre line.
#pragma once

#include <optional>

#include "policies.h"
#include "step_controller.h"

namespace olympics::client {

class ScriptedHurdlesPolicy : public Policy {
 public:
  void start(const MatchInfo& match) override;
  void act(std::span<const float> observation, std::span<float> action) override;

 private:
  int goal_ = 0, first_ = 0;  // where the goal and the first hurdle start in the observation
  std::optional<StepController> legs_;
};

}  // namespace olympics::client
