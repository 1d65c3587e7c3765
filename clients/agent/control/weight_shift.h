// Timed plans of LegSupport for hold_on_legs. WeightShiftPlan: settle on both feet, carry the
// weight over the stance foot by a minimum-jerk blend, lift the other foot, hold it up, put it
// down, carry the weight back to the middle. SteppingPlan: steps in place, the weight carried
// from foot to foot and the free foot lifted each time.
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

// Steps in place or forward (reach_m), the first onto the left foot: each step carries the weight
// across (from the middle, the first, in half the time), waits on the foot, lifts the other, holds
// it, puts it down. Measured (docs/basketball.md, "A weight shift onto one leg"), falls a minute of
// both players of a 1v1: across in 5 s, 0.75 on unseen seeds; in 4 s, 1.4; in 3.5 s, 1.5 on seeds
// 1-3.
struct SteppingPlan {
  double settle_s = 1.0;  // on both feet first
  double across_s = 5.0;  // the weight carried from one foot to the other
  double loaded_s = 0.6;  // on the foot before the other is lifted
  double lift_s = 0.4;    // the free foot raised (and lowered)
  double hold_s = 0.3;    // held up
  double lift_m = 0.06;   // asked (it rises 4-7 cm)
  // A walk forward: the free foot swung, while up, from reach_m behind the stance ankle (beside
  // it at the first step) to reach_m ahead, and put down there; the weight carried onto it then
  // carries the body on. 0: in place.
  double reach_m = 0.0;

  double step_s() const { return across_s + loaded_s + 2 * lift_s + hold_s; }
  // Steps whose foot has begun to rise by `t`.
  int steps_lifted(double t) const;
  LegSupport at(double t) const;
};

// The slow walk forward (docs/basketball.md, "A slow walk forward on the weight shift"): steps
// in place as above with the free foot put 5 cm ahead, on slow_walk_gains(). Measured, both
// players of full-court 1v1s: 0.20 falls and 0.62 m forward a minute at 8.5 steps a minute on
// unseen seeds (main's steps in place: 0.33 falls, 0.67 m backward); 10 cm steps fell 2.0 times
// a minute on the tuning seeds.
SteppingPlan slow_walk_plan();
// hold_on_legs' gains for it: the centre of mass held over the ankles, not 3 cm ahead (ahead,
// steps in place drift back about 7 cm each, which 5 cm steps do not outrun), and its forward
// motion damped harder (200 N·m per m/s; 120: 0.30 falls a minute).
LegSupportGains slow_walk_gains();

// A walk of 10 cm steps (docs/basketball.md, "Why the body turned"): the slow walk with the free
// foot put twice as far ahead, on stride_walk_gains(). Measured, both players of full-court 1v1s:
// 1.00 m forward and 0.32 falls a minute on unseen seeds (the slow walk on the same seeds: 0.60 m,
// 0.26 falls).
SteppingPlan stride_walk_plan();
// slow_walk_gains() with the hip of a leg carrying under 15% of the weight free in yaw (10 cm
// steps on slow_walk_gains(): 1.97 falls a minute on tuning seeds; free: 0.23).
LegSupportGains stride_walk_gains();

}  // namespace olympics::client::control
