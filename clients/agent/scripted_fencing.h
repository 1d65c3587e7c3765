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
#include "control/guard_footwork.h"
#include "policies.h"

namespace olympics::client {

class ScriptedFencingPolicy : public Policy {
 public:
  void start(const MatchInfo& match) override;
  void act(std::span<const float> observation, std::span<float> action) override;

  // True from the front foot's leaving the ground in a lunge until the lunge's hold ends: a
  // touch scored then came from a lunge.
  bool lunging() const;
  int debug_stage() const { return legs_ ? 10 * (int)legs_->move() + (int)legs_->stage() : -1; }

 private:
  struct Blocks {  // where the observation's fields it reads start
    int opponent = 0, opponent_velocity = 0, chest = 0, tip = 0, across = 0, to_my_end = 0;
  };
  using Move = control::GuardFootwork::Move;
  Move choose(std::span<const float> observation);

  Blocks blocks_;
  double control_dt_ = 0;
  std::optional<control::GuardFootwork> legs_;
  ArmDirection arm_{Arm::Right};
  double in_guard_s_ = 0;  // time at guard distance since the last attack
  bool attacking_ = false;
  double last_distance_ = 0;  // root to root a tick ago
};

}  // namespace olympics::client
