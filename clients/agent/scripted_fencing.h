// The scripted baseline for fencing: the yardstick learned fencers must beat. It reads only the
// observation (blocks by name):
//
// - it faces the opponent and walks (StepController) to just out of reach, on the line between
//   the two roots;
// - it holds the épée pointed at the opponent's chest from the shoulder, arm straight;
// - it attacks: steps in until the tip has driven into the target, then falls back out of reach
//   and attacks again, over and over;
// - near its end of the piste it does not retreat further.
#pragma once

#include <optional>

#include "arm_control.h"
#include "policies.h"
#include "step_controller.h"

namespace olympics::client {

class ScriptedFencingPolicy : public Policy {
 public:
  void start(const MatchInfo& match) override;
  void act(std::span<const float> observation, std::span<float> action) override;

 private:
  struct Blocks {  // where the observation's fields it reads start
    int opponent = 0, chest = 0, to_my_end = 0;
  };
  enum class Phase { Approach, Attack, Recover };

  Blocks blocks_;
  double control_dt_ = 0;
  std::optional<StepController> legs_;
  ArmDirection arm_{Arm::Right};
  Phase phase_ = Phase::Approach;
  double phase_s_ = 0;
};

}  // namespace olympics::client
