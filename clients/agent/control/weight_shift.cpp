#include "control/weight_shift.h"

#include "control/minimum_jerk.h"

namespace olympics::client::control {
LegSupport WeightShiftPlan::at(double t) const {
  // The stance foot's share: 0.5 -> stance_share over the shift, back over the return.
  const double out = (t - settle_s) / shift_s;
  const double back = (t - (back_at() - shift_s)) / shift_s;
  const double gain = stance_share - 0.5;
  double share = 0.5 + gain * (minimum_jerk(out) - minimum_jerk(back));
  double rate = gain * (minimum_jerk_rate(out, shift_s) - minimum_jerk_rate(back, shift_s));
  // The free foot: raised over lift_s, held, lowered over lift_s.
  const double up = (t - (lifted_at() - lift_s)) / lift_s;
  const double down = (t - held_until()) / lift_s;
  const double lift = lift_m * (minimum_jerk(up) - minimum_jerk(down));
  LegSupport s;
  s.left_share = onto_left ? share : 1 - share;
  s.left_share_rate = onto_left ? rate : -rate;
  s.lift[onto_left ? 1 : 0] = lift;
  return s;
}

int SteppingPlan::steps_lifted(double t) const {
  // Step k starts at settle_s + k step_s (less the first's shortened crossing) and lifts after
  // its crossing and wait.
  const double first_lift = settle_s + 0.5 * across_s + loaded_s;
  if (t < first_lift) return 0;
  return 1 + static_cast<int>((t - first_lift) / step_s());
}

LegSupport SteppingPlan::at(double t) const {
  LegSupport s;
  if (t < settle_s) return s;
  // The first step crosses from the middle in half the time; later ones from foot to foot.
  const double first = step_s() - 0.5 * across_s;
  const bool later = t - settle_s >= first;
  const int k = later ? 1 + static_cast<int>((t - settle_s - first) / step_s()) : 0;
  const double u = later ? t - settle_s - first - (k - 1) * step_s() : t - settle_s;
  const double across = later ? across_s : 0.5 * across_s;
  const bool onto_left = k % 2 == 0;
  const double from = later ? (onto_left ? 0.0 : 1.0) : 0.5, to = onto_left ? 1.0 : 0.0;
  s.left_share = from + (to - from) * minimum_jerk(u / across);
  s.left_share_rate = (to - from) * minimum_jerk_rate(u / across, across);
  const double since_lift = u - across - loaded_s;  // < 0 while the weight crosses and settles
  const double up = since_lift / lift_s;
  const double down = (since_lift - lift_s - hold_s) / lift_s;
  s.lift[onto_left ? 1 : 0] = lift_m * (minimum_jerk(up) - minimum_jerk(down));
  // The free foot's place ahead of the stance ankle: from behind it (beside it at the first
  // step) to reach_m ahead over the lift and hold, then kept.
  const double behind = later ? -reach_m : 0.0;
  const double free_ahead =
      behind + (reach_m - behind) * minimum_jerk(since_lift / (lift_s + hold_s));
  s.left_ahead = onto_left ? -free_ahead : free_ahead;
  return s;
}

SteppingPlan slow_walk_plan() {
  SteppingPlan plan;
  plan.reach_m = 0.05;
  return plan;
}

LegSupportGains slow_walk_gains() {
  LegSupportGains gains;
  gains.ahead = 0;
  gains.forward_d = 200;
  return gains;
}

SteppingPlan stride_walk_plan() {
  SteppingPlan plan = slow_walk_plan();
  plan.reach_m = 0.10;
  return plan;
}

LegSupportGains stride_walk_gains() {
  LegSupportGains gains = slow_walk_gains();
  gains.free_hip_yaw_below = 0.15;
  return gains;
}

}  // namespace olympics::client::control
