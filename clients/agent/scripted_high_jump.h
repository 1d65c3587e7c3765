// The scripted high jumper: it walks (quicker steps than the walker's default) onto the line
// square to the middle of the bar, along it to a stop in front of the bar, and on arriving
// there, still walking, makes a two-footed jump forward with its knees tucked over the bar
// (control::WalkAndJump) — a low bar's clearance, not a Fosbury flop. From the
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
  double stop_m = 0.8;  // m: the root's stop before the bar's plane, where it jumps
  // The seed's bar is 21 m away (20 ahead, 6 to the left) and an attempt lasts 20 s: at the
  // walker's default ~0.8 m/s the walk took the whole attempt.
  control::JumpApproach approach = seed_approach();
  static control::JumpApproach seed_approach();
  static control::StandingJump tucked_jump();
};

class ScriptedHighJumpPolicy : public Policy {
 public:
  explicit ScriptedHighJumpPolicy(const HighJumpPlan& plan = {}) : plan_(plan) {}
  void start(const MatchInfo& match) override;
  void act(std::span<const float> observation, std::span<float> action) override;
  bool jumping() const { return jumper_ && jumper_->jumping(); }

 private:
  HighJumpPlan plan_;
  int bar_ = 0, time_left_ = 0;
  std::optional<control::WalkAndJump> jumper_;
  double last_time_left_ = 2;
};

}  // namespace olympics::client
