// The scripted high jumper: it walks to a stop in front of the middle of the bar, square to it,
// stands until it is still, then makes a standing two-footed jump forward with its knees tucked
// over the bar (control::WalkAndJump) — a low bar's clearance, not a Fosbury flop. From the
// observation alone, by name: the bar's two ends give where its middle is and which way is over;
// it starts again with each attempt (the attempt's time left jumps back up).
//
// The jump's poses and times were found by a search on tuning seeds (docs/athletics.md "The
// scripted jumpers").
#pragma once

#include <optional>

#include "control/walk_and_jump.h"
#include "policies.h"

namespace olympics::client {

struct HighJumpPlan {
  double stop_m = 0.45;  // m: the root's stop before the bar's plane
  // The seed's bar is 21 m away and an attempt lasts 20 s: it asks the walker for 2 m/s (it
  // makes about 1.2).
  control::JumpApproach approach{.still_s = 0.3, .walk_speed = 2.0, .jump = tucked_jump()};
  static control::StandingJump tucked_jump();
};

class ScriptedHighJumpPolicy : public Policy {
 public:
  explicit ScriptedHighJumpPolicy(const HighJumpPlan& plan = {}) : plan_(plan) {}
  void start(const MatchInfo& match) override;
  void act(std::span<const float> observation, std::span<float> action) override;

 private:
  HighJumpPlan plan_;
  int bar_ = 0, time_left_ = 0;
  std::optional<control::WalkAndJump> jumper_;
  double last_time_left_ = 2;
};

}  // namespace olympics::client
