// A timed weight shift onto one leg and back, as LegSupport plans for hold_on_legs: settle on
// both feet, carry the weight over the stance foot by a minimum-jerk blend, lift the other foot,
// hold it up, put it down, carry the weight back to the middle.
#pragma once

#include "control/leg_support.h"

namespace olympics::client::control {

struct WeightShiftPlan {
  bool onto_left = true;
  double settle_s = 1.0;      // on both feet before the shift
  double shift_s = 3.0;       // the weight carried over the stance foot (and back); 2 s fell often
  double loaded_s = 0.5;      // over the stance foot before the lift
  double down_s = 0.0;        // and after the free foot is put down, before the shift back
  double lift_s = 0.4;        // the free foot raised (and lowered)
  double hold_s = 1.0;        // held up
  double lift_m = 0.06;       // asked; the stance leg sags, so the foot rises 3-5 cm
  double stance_share = 1.0;  // of the weight on the stance foot once shifted

  // When each phase ends, s from the start.
  double shifted_at() const { return settle_s + shift_s; }
  double lifted_at() const { return shifted_at() + loaded_s + lift_s; }
  double held_until() const { return lifted_at() + hold_s; }
  double lowered_at() const { return held_until() + lift_s; }
  double back_at() const { return lowered_at() + down_s + shift_s; }

  // What the legs are asked at `t` s from the start.
  LegSupport at(double t) const;
};

}  // namespace olympics::client::control
