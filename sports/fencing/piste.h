// The piste (SPORTS.md: 14 x 2 m, the seed's; real pistes are 14 x 1.5-2 m) along the x axis,
// centred on the origin. Fencer 0 (team 0) stands on its on-guard line at x = -on_guard facing
// +x, fencer 1 at x = +on_guard facing -x.
#pragma once

#include "core/humanoid.h"
#include "framework/area.h"

namespace olympics::sports::fencing {

struct Piste {
  double length = 14, width = 2;
  double on_guard = 2;  // each on-guard line's distance from the centre line

  GroundRect area() const { return GroundRect::centred(length, width); }
  static int side(int fencer) { return fencer == 0 ? -1 : 1; }
  // On the on-guard line, facing the other fencer; `jitter` (each in [-1, 1]: along, across,
  // turn) moves the fencer by up to 0.1 m and turns it by up to 0.1 rad, so that seeds differ.
  core::RootPlacement on_guard_placement(int fencer, const Eigen::Vector3d& jitter) const {
    return {{side(fencer) * on_guard + 0.1 * jitter.x(), 0.1 * jitter.y(), 0},
            (fencer == 0 ? 0.0 : M_PI) + 0.1 * jitter.z()};
  }
};

}  // namespace olympics::sports::fencing
