#include "smplx_observation.h"

#include <Eigen/Geometry>
#include <cmath>

namespace olympics::client::smplx {
namespace {

// The action scale of joint `body`'s hinge `axis`, from the hinge ranges of HUMANOID-SMPLX.md.
double scale(int body, int axis) {
  constexpr double deg = M_PI / 180;
  auto from_range = [](double bound_deg) { return std::min(1.2 * bound_deg * deg, M_PI); };
  switch (body) {
    case 1:
    case 5:
    case 3:
    case 7:
    case 13:  // hips, ankles, head: +-90
      return from_range(90);
    case kLKnee:
    case kRKnee:
      return axis == 1 ? 5.0 : from_range(5.625);
    case 4:
    case 8:  // toes: x +-45, y +-90, z +-45
      return from_range(axis == 1 ? 90 : 45);
    case 9:
    case 10:
    case 11:  // torso, spine, chest: +-60
      return from_range(60);
    default:  // neck, arms, hands, fingers: +-180 or more
      return M_PI;
  }
}

}  // namespace

Eigen::Matrix3d body_rotation(std::span<const float> o, int body) {
  const Eigen::Vector3d x = vec3(o, kSelf.body_rotation(body)).normalized();
  const Eigen::Vector3d z = vec3(o, kSelf.body_rotation(body) + 3).normalized();
  Eigen::Matrix3d r;
  r << x, z.cross(x), z;
  return r;
}

void set_joint(std::span<float> action, int body, int axis, double radians) {
  action[3 * (body - 1) + axis] = static_cast<float>(radians / scale(body, axis));
}

double joint_angle(std::span<const float> action, int body, int axis) {
  return action[3 * (body - 1) + axis] * scale(body, axis);
}

}  // namespace olympics::client::smplx
