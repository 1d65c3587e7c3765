// The scripted long jumper: it walks down its runway to a stop just behind the foul line and
// makes a two-footed jump into the pit (control::WalkAndJump): from a start near the line it
// stands still at its stop first; after a walk down the runway it jumps on arriving, still walking.
// From the observation alone, by name: the foul line's point on its runway's centre and the
// seed's goal (10 m further down the same centre line) give it the runway's direction; it
// starts again with each attempt (the attempt's time left jumps back up).
//
// A floor for learned jumpers, not a long jumper an official would recognise: no run-up speed
// at the take-off beyond a walk's. The jump's poses and times were found by a search on tuning
// seeds (docs/athletics.md "The scripted jumpers").
#pragma once

#include <optional>

#include "control/walk_and_jump.h"
#include "policies.h"

namespace olympics::client {

// Where it stops behind the line and how it jumps from there.
struct LongJumpStage {
  // m: the root's stop behind the line. The toes reach ~0.25 m ahead of the root, the crouch's
  // head and hands further, and the walker stops within 0.12 m or so of where it is sent.
  double stop_m;
  control::JumpApproach approach;
};

struct LongJumpPlan {
  // From a start mark near the line (the standing long jump's 0.8 m): stand still at the stop,
  // then jump.
  LongJumpStage standing{.stop_m = 0.8, .approach = {.jump = standing_long_jump()}};
  // After a walk down the runway: jump on arriving at the stop, still walking at ~0.8 m/s (the
  // walk leaves the body moving; standing still there toppled it or stepped to and fro).
  LongJumpStage walk_up{.stop_m = 1.3, .approach = {.still_s = 0, .jump = walking_long_jump()}};
  // m from the start mark to the line beyond which it walks up.
  double walk_up_beyond_m = 2.0;
  static control::StandingJump standing_long_jump();
  static control::StandingJump walking_long_jump();
};

class ScriptedLongJumpPolicy : public Policy {
 public:
  explicit ScriptedLongJumpPolicy(const LongJumpPlan& plan = {}) : plan_(plan) {}
  void start(const MatchInfo& match) override;
  void act(std::span<const float> observation, std::span<float> action) override;

 private:
  LongJumpPlan plan_;
  int line_ = 0, goal_ = 0, time_left_ = 0;
  double control_dt_ = 0;
  std::optional<control::WalkAndJump> jumper_;  // this attempt's, from its first observation
  const LongJumpStage* stage_ = nullptr;
  double last_time_left_ = 2;
};

}  // namespace olympics::client
