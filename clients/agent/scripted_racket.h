// The scripted baseline for tennis and table tennis: the yardstick that learned policies must
// beat. It reads only the observation, finding its blocks by name:
//
// - prediction: the ball's path is stepped forward (gravity, one bounce on the court or table) to
//   where it crosses a plane just in front of the player;
// - moving: while the ball comes to its side, a StepController walks the player sideways so that
//   point falls under the racket, and turns it back to face the net; otherwise it stands (ankle
//   and hip balance) or walks back toward the middle of its half;
// - reach and swing: the right arm points the racket at the crossing point with the face turned
//   to the net, drawn back while the ball is far and swung through as it arrives.
#pragma once

#include <optional>

#include "policies.h"
#include "step_controller.h"

namespace olympics::client {

class ScriptedRacketPolicy : public Policy {
 public:
  void start(const MatchInfo& match) override;
  void act(std::span<const float> observation, std::span<float> action) override;

  // Where the blocks it reads lie (match_info.h).
  struct Blocks {
    int ball = 0, ball_velocity = 0, target = 0, court_position = 0, court_heading = 0, rally = 0;
  };

 private:
  Blocks blocks_;
  bool table_ = false;
  double control_dt_ = 0;
  std::optional<StepController> legs_;
};

}  // namespace olympics::client
