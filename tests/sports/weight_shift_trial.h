// One weight shift onto a leg and back (clients/agent/control/weight_shift.h) by a humanoid of a
// real match, measured: SMPL-X players standing in a basketball 1v1 (both shift, each its own
// trial), or the sandbox's solo SMPL humanoid.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "control/leg_support.h"
#include "control/weight_shift.h"

namespace olympics::sports {

struct ShiftTrial {
  // At the end of the shift plus the wait before the lift: the centre of mass's sideways distance
  // from the stance foot's centre (the foot box's) and from its ankle.
  double off_foot_m = 0, off_ankle_m = 0;
  double lift_min_m = 0;   // the free foot's least height over where it stood, through the hold
  double lift_mean_m = 0;  // and its mean
  bool fell = false;       // a fall called by the match in the trial (plan.back_at() + 1 s)
  double fell_at_s = -1;

  bool shifted() const { return off_foot_m < 0.03; }
  bool lifted() const { return lift_min_m > 0.02; }
  bool success() const { return shifted() && lifted() && !fell; }
};

// SMPL-X: a basketball 1v1 of `seed`; both players shift (slot 0 onto `plan.onto_left`'s foot,
// slot 1 onto the other): two trials. SMPL: the sandbox's solo, one trial.
std::vector<ShiftTrial> shift_trials(bool smplx, std::uint64_t seed,
                                     client::control::WeightShiftPlan plan,
                                     const client::control::LegSupportGains& gains,
                                     bool half_and_half = false);

std::string describe(const ShiftTrial& t);

struct Stepping {
  int falls = 0;       // of both players
  int steps = 0;       // feet lifted, both players
  double minutes = 0;  // player-minutes
};

// Both SMPL-X players of a basketball 1v1 of `seed` step in place by `plan` for `seconds`; a
// fallen player is stood up by the match and starts its plan again.
Stepping step_in_place(std::uint64_t seed, double seconds,
                       const client::control::SteppingPlan& plan,
                       const client::control::LegSupportGains& gains);

struct Walking {
  int falls = 0;         // of both players
  int steps = 0;         // feet lifted, both players
  double minutes = 0;    // player-minutes (the trial's time, falls and all)
  double forward_m = 0;  // both players' centre of mass carried forward along their heading,
                         // a walk that fell counted up to its last lift
  std::vector<double> forward_each_m;  // each player's, slot 0 then 1
};

// Both SMPL-X players of a full-court basketball 1v1 of `seed` (6 m apart, facing each other)
// walk by `plan` on `gains` for `seconds`, or until a restart moves them (the dropped check ball
// rolling out) or they come within 1.5 m; a fallen player is stood up by the match and starts
// its plan again.
Walking walk_forward(std::uint64_t seed, double seconds, const client::control::SteppingPlan& plan,
                     const client::control::LegSupportGains& gains);

}  // namespace olympics::sports
