// The scripted baseline for boxing: the yardstick learned boxers must beat. It reads only the
// observation (blocks by name):
//
// - it faces the opponent and walks (StepController) to punching range, each boxer closing half
//   the gap; there it plants both feet, knees bent, and balances its centre of mass over them
//   with the ankles (never while backing off: planted, it would tip over backward); it steps
//   again only when the distance or the opponent's bearing drifts;
// - it holds a guard: upper arms forward and down, elbows bent, gloves up before the chin;
// - planted and in range it punches (never from a step): left jab and right cross in turn, each arm
//   thrown straight at the opponent's chest, under its guard, with the trunk leaning into the
//   punch and turning the punching shoulder forward, and drawn back to the guard; a punch that
//   would not reach even so is not thrown;
// - it stands still during the rest between rounds.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "policies.h"
#include "step_controller.h"

namespace olympics::client {

// The boxer's legs: the stepping controller, slow in the approach, turning to face the opponent.
StepGains boxing_step_gains();

// The boxer's guard: upper arms forward and down, elbows bent, gloves up before the chin.
void hold_guard(std::span<const float> observation, std::span<float> action);

class ScriptedBoxingPolicy : public Policy {
 public:
  // `legs`: the stepping controller's gains (a test tries others).
  explicit ScriptedBoxingPolicy(const StepGains& legs = boxing_step_gains()) : gains_(legs) {}
  void start(const MatchInfo& match) override;
  void act(std::span<const float> observation, std::span<float> action) override;

  // What act() reads of the bout besides the body (heading frame, from the root).
  struct Bout {
    Eigen::Vector3d opponent{0, 0, 0};  // the opponent's root
    Eigen::Vector3d chest{0, 0, 0};     // where its punches go
    bool resting = false;               // between rounds
  };
  // Alone, with no bout's observation (a test in the sandbox's solo mode before a point it takes
  // for its opponent): start with the tick's length, then act against the bout it is given.
  void start_alone(double control_dt);
  void act_against(std::span<const float> self, const Bout& bout, std::span<float> action);
  // Both feet planted where they stand (punching when in range), as of the last act().
  bool planted() const { return planted_; }

 private:
  struct Blocks {  // where the observation's fields it reads start
    int opponent = 0, chest = 0, resting = 0;
  };
  Blocks blocks_;
  double control_dt_ = 0;
  std::optional<StepController> legs_;
  StepGains gains_;
  bool planted_ = false;      // both feet down where they stand, punching
  bool was_resting_ = false;  // to see the bell
  double clock_s_ = 0;        // time in range, for the punches' rhythm
};

}  // namespace olympics::client
