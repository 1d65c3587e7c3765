// The scripted baseline for fencing: the yardstick learned fencers must beat. It reads only the
// observation (blocks by name):
//
// - it faces the opponent and walks (StepController) to just out of reach, on the line between
//   the two roots;
// - it holds the épée pointed at the opponent's chest from the shoulder, arm straight;
// - in guard it keeps out of reach (2.1 m root to root), arm half bent; it closes toward the
//   opponent, straightens the arm within 1.85 m, and lunges from 1.65 m: the front foot's next
//   step becomes a 0.35 m lunge while the back leg straightens; it holds, then recovers out of
//   reach with the stepping controller, and attacks again, over and over;
// - it leans back toward the piste's middle when off it sideways;
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
    int opponent = 0, chest = 0, to_my_end = 0, across = 0;
  };
  enum class Phase { Guard, Close, Lunge, Recover };
  void enter(Phase phase);

  Blocks blocks_;
  double control_dt_ = 0;
  StepGains gains_;
  std::optional<StepController> legs_;
  ArmDirection arm_{Arm::Right};
  Phase phase_ = Phase::Guard;
  double phase_s_ = 0;
  // The front (right) ankle from the back (left) one at the lunge's launch (heading frame).
  Eigen::Vector3d front_from_back_{0, 0, 0};
};

}  // namespace olympics::client
