// Landing prediction (SPORTS.md, shared pieces; the seed's eq. 6): where a ball at p0 with
// velocity v0 comes down to height h on a drag-free parabola. A dense reward signal in every
// sport where a ball should land somewhere.
#pragma once

#include <Eigen/Core>

namespace olympics::sports::equipment {

// T = (v0z + sqrt(v0z^2 + 2 g (z0 - h))) / g; landing (x0 + v0x T, y0 + v0y T). When the ball
// can no longer reach h going down (below it and the root is imaginary), T is the time to the
// top of its arc (0 if falling): the landing is where it is now, or under its apex.
Eigen::Vector2d predict_landing(const Eigen::Vector3d& p0, const Eigen::Vector3d& v0, double h,
                                double g = 9.81);

}  // namespace olympics::sports::equipment
