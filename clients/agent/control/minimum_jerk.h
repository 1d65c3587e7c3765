// A blend for scripted motions: 0 to 1 over [0, 1] with zero velocity and acceleration at both
// ends (the minimum-jerk profile), clamped outside it.
#pragma once

#include <algorithm>

namespace olympics::client::control {

inline double minimum_jerk(double s) {
  s = std::clamp(s, 0.0, 1.0);
  return s * s * s * (10 - 15 * s + 6 * s * s);
}

// The blend's rate (1/s) at fraction s of a blend lasting `seconds`; 0 outside it.
inline double minimum_jerk_rate(double s, double seconds) {
  if (s <= 0 || s >= 1) return 0;
  return 30 * s * s * (1 - s) * (1 - s) / seconds;
}

}  // namespace olympics::client::control
