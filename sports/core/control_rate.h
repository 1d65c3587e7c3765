// The control rate: policies act, and matches tick, 30 times a second (HUMANOID.md section 2:
// the original runs its policies at 30 Hz). The one place this number is written: it is the
// scenes' default (SceneSettings::control_dt), and the server tells clients each match's own
// rate (SportMatch::control_hz(), match_created_t.control_hz).
#pragma once

namespace olympics::core {

inline constexpr int kControlHz = 30;
inline constexpr double kControlDt = 1.0 / kControlHz;

}  // namespace olympics::core
