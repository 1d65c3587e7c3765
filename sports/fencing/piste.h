// The piste (SPORTS.md: 14 x 2 m, the seed's; real pistes are 14 x 1.5-2 m) along the x axis,
// centred on the origin. Fencer 0 (team 0) stands on its on-guard line at x = -on_guard facing
// +x, fencer 1 at x = +on_guard facing -x (combat/start_placement.h).
#pragma once

#include "framework/area.h"

namespace olympics::sports::fencing {

struct Piste {
  double length = 14, width = 2;
  double on_guard = 2;  // each on-guard line's distance from the centre line

  GroundRect area() const { return GroundRect::centred(length, width); }
};

}  // namespace olympics::sports::fencing
