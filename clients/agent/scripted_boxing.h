// The scripted baseline for boxing: the yardstick learned boxers must beat. It reads only the
// observation (blocks by name):
//
// - it faces the opponent and moves in and out (StepController): in to punching range for a
//   combination, then back out of reach, so that the two do not stand chest to chest;
// - it holds a guard: upper arms forward and down, elbows bent, gloves up before the chin;
// - in range it punches: left jab and right cross in turn, each arm thrown straight at the
//   opponent's head or chest and drawn back to the guard;
// - it stands still during the rest between rounds.
#pragma once

#include <optional>

#include "policies.h"
#include "step_controller.h"

namespace olympics::client {

class ScriptedBoxingPolicy : public Policy {
 public:
  void start(const MatchInfo& match) override;
  void act(std::span<const float> observation, std::span<float> action) override;

 private:
  struct Blocks {  // where the observation's fields it reads start
    int opponent = 0, chest = 0, head = 0, resting = 0;
  };
  Blocks blocks_;
  double control_dt_ = 0;
  std::optional<StepController> legs_;
  double clock_s_ = 0;  // time in range, for the punches' rhythm
  double cycle_s_ = 0;  // time into the in-and-out cycle
};

}  // namespace olympics::client
