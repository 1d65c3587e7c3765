#include "control/smpl_legs.h"

namespace olympics::client::control {

std::vector<LimbJoint> smpl_leg(bool left) {
  const int hip = left ? kSmplLHip : kSmplRHip;
  return {
      {hip, {-1.3, -2.0, -0.8}, {1.3, 1.2, 0.8}, {0, -0.15, 0}},
      {hip + 1, {-0.1, 0.0, -0.1}, {0.1, 2.6, 0.1}, {0, 0.3, 0}},
      {hip + 2, {-0.78, -1.2, -0.5}, {0.78, 1.2, 0.5}, {0, -0.15, 0}},
  };
}

Eigen::Vector3d smpl_toe_front(bool left) {
  // The toe body sits at (.1233, -+.0254, -.0481) in the ankle's frame, its box reaching .0227 +
  // .0493 further forward (HUMANOID.md); the front face's middle.
  return {0.19, left ? 0.025 : -0.025, -0.044};
}

}  // namespace olympics::client::control
