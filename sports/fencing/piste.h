// The piste (SPORTS.md: 14 x 2 m, the seed's; real pistes are 14 x 1.5-2 m) along the x axis,
// centred on the origin. Fencer 0 (team 0) stands on its on-guard line at x = -on_guard facing
// +x, fencer 1 at x = +on_guard facing -x (combat/start_placement.h).
#pragma once

#include "framework/area.h"
#include "framework/scene_view.h"

namespace olympics::sports::fencing {

struct Piste {
  double length = 14, width = 2;
  double on_guard = 2;  // each on-guard line's distance from the centre line

  GroundRect area() const { return GroundRect::centred(length, width); }
  // The strip, its centre and on-guard lines, for viewers.
  void describe(SceneBuilder& scene) const {
    scene.set_ground(length / 2 + 3, width / 2 + 3, "#5a5f66");
    scene.add_box(-1, {0, 0, -0.01}, {length / 2, width / 2, 0.011}, "arena", "#b9c2c9");
    scene.add_ground_rect(-length / 2, length / 2, -width / 2, width / 2, "line");
    for (double x : {-on_guard, 0.0, on_guard})
      scene.add_line({x, -width / 2, 0.002}, {x, width / 2, 0.002}, "line");
  }
};

}  // namespace olympics::sports::fencing
