// The scripted javelin thrower (SMPL-X): a standing throw with a timed release, the yardstick
// learned throwers must beat. From the observation alone (its clock restarts with each attempt):
//
// - hold: the right hand's fingers close on the cord (the grip holds the javelin while they are
//   closed) and the right arm goes to the hold pose in 0.4 s;
// - swing: at `swing_s` the arm's targets step to the swing pose: it moves as fast as its
//   drives allow;
// - release: `release_ticks` control ticks into the swing the fingers open and the javelin
//   flies.
// The poses and times were found by a search (cross-entropy over the tuning seeds 1-3,
// docs/athletics.md "The scripted thrower"); the legs keep the zero pose: the throw is over
// within about a second, before the body topples.
#pragma once

#include <array>

#include "policies.h"

namespace olympics::client {

// Targets (rad) of the right arm's joints: shoulder x, y, z; elbow x, y, z; wrist x, y, z.
using ArmTargets = std::array<double, 9>;

struct JavelinThrow {
  double curl = 0.4;  // rad per finger joint: closed on the cord
  // Found by the search (the mean of its last elite): the arm raised and turned back, the
  // forearm rolled so that the javelin points forward and down; the swing forward and across.
  ArmTargets hold = {-0.929, 0.052, -1.315, -0.032, -0.126, -1.960, 0.953, -0.356, 1.262};
  ArmTargets swing = {-1.407, -0.704, 1.157, -0.817, -0.474, -0.433, -0.019, 0.772, -0.177};
  double swing_s = 0.810;  // s from the attempt's start
  int release_ticks = 1;   // control ticks into the swing
};

class ScriptedJavelinPolicy : public Policy {
 public:
  explicit ScriptedJavelinPolicy(const JavelinThrow& t = {}) : throw_(t) {}
  void start(const MatchInfo& match) override;
  void act(std::span<const float> observation, std::span<float> action) override;

 private:
  JavelinThrow throw_;
  int time_left_ = 0;
  double control_dt_ = 0;
  int tick_ = 0;
  double last_time_left_ = 2;
};

}  // namespace olympics::client
