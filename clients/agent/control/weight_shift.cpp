#include "control/weight_shift.h"

#include "control/minimum_jerk.h"

namespace olympics::client::control {
namespace {

// The minimum-jerk blend's rate at fraction s of a blend lasting `seconds`.
double minimum_jerk_rate(double s, double seconds) {
  if (s <= 0 || s >= 1) return 0;
  return 30 * s * s * (1 - s) * (1 - s) / seconds;
}

}  // namespace

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

}  // namespace olympics::client::control
