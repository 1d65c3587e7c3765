#include "scripted_javelin.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "control/minimum_jerk.h"
#include "smplx_observation.h"

namespace olympics::client {
namespace {

using namespace smplx;

void set_arm(std::span<float> a, const ArmTargets& targets, double share) {
  const int joints[] = {kRShoulder, kRElbow, kRWrist};
  for (int j = 0; j < 3; ++j)
    for (int axis = 0; axis < 3; ++axis)
      set_joint(a, joints[j], axis, share * targets[3 * j + axis]);
}

}  // namespace

void ScriptedJavelinPolicy::start(const MatchInfo& match) {
  if (match.sport != "javelin")
    throw std::invalid_argument("the scripted javelin policy throws javelins, not " + match.sport);
  time_left_ = match.observation.offset("attempt", "time_left");
  control_dt_ = match.control_dt;
  tick_ = 0;
  last_time_left_ = 2;
}

void ScriptedJavelinPolicy::act(std::span<const float> o, std::span<float> a) {
  if (a.size() != kActions || o.size() < static_cast<size_t>(kSelfObservation))
    throw std::invalid_argument("the scripted javelin policy plays the SMPL-X humanoid");
  std::fill(a.begin(), a.end(), 0.0f);
  if (o[time_left_] > last_time_left_ + 1e-6) tick_ = 0;  // the next attempt
  last_time_left_ = o[time_left_];
  const double t = tick_ * control_dt_;
  const int swing_tick = static_cast<int>(std::lround(throw_.swing_s / control_dt_));
  if (tick_ < swing_tick)
    set_arm(a, throw_.hold, control::minimum_jerk(t / 0.4));
  else
    set_arm(a, throw_.swing, 1.0);
  if (tick_ < swing_tick + throw_.release_ticks)
    for (int f = 0; f < kLinksBeforeThumb; ++f) set_joint(a, kRFingers + f, 0, throw_.curl);
  ++tick_;
}

std::unique_ptr<Policy> make_scripted_javelin() {
  return std::make_unique<ScriptedJavelinPolicy>();
}

}  // namespace olympics::client
