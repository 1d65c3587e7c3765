// The scripted baseline for fencing: the yardstick learned fencers must beat. It reads only the
// observation (blocks by name):
//
// - it faces the opponent and walks (StepController) to just out of reach, on the line between
//   the two roots, in a guard: at every step the right (front) foot lands 0.1 m ahead of the
//   left (back) one; when the opponent comes in, it gives ground;
// - it holds the épée pointed at the opponent's chest from the shoulder, arm straight;
// - it attacks: steps in, and lunges when the tip is within 0.45 m of the chest (the front foot
//   flies 0.3 m on while the back leg straightens, taken over as that foot leaves the ground in
//   a step), or goes on until the tip has driven into the target; then falls back out of reach
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

  // True from the front foot's leaving the ground in a lunge to 0.3 s after it lands: a touch
  // scored then came from a lunge.
  bool lunging() const;

 private:
  struct Blocks {  // where the observation's fields it reads start
    int opponent = 0, opponent_velocity = 0, chest = 0, tip = 0, to_my_end = 0;
  };
  enum class Phase { Approach, Attack, Lunge, Recover };
  void enter(std::span<const float> observation, Phase phase);

  Blocks blocks_;
  double control_dt_ = 0;
  StepGains gains_;
  std::optional<StepController> legs_;
  Eigen::Vector2d front_from_back_{0, 0};
  bool after_lunge_ = false;  // the phase now began at a lunge's end  // the front ankle from the
                              // back one at the launch
  ArmDirection arm_{Arm::Right};
  Phase phase_ = Phase::Approach;
  double phase_s_ = 0;
};

}  // namespace olympics::client
