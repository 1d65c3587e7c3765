#include "smpl_observation.h"

#include <Eigen/Geometry>
#include <cmath>

namespace olympics::client::smpl {

Eigen::Matrix3d body_rotation(std::span<const float> o, int body) {
  const Eigen::Vector3d x = vec3(o, kSelf.body_x_axis(body)).normalized();
  const Eigen::Vector3d z = vec3(o, kSelf.body_z_axis(body)).normalized();
  Eigen::Matrix3d r;
  r << x, z.cross(x), z;
  return r;
}

namespace {
// HUMANOID.md: PD target = pi a per axis, knee flexion 5 a.
double action_scale(int body, int axis) {
  return (body == kLKnee || body == kRKnee) && axis == 1 ? 5.0 : M_PI;
}
}  // namespace

void set_joint(std::span<float> action, int body, int axis, double radians) {
  action[3 * (body - 1) + axis] = static_cast<float>(radians / action_scale(body, axis));
}

double joint_angle(std::span<const float> action, int body, int axis) {
  return action[3 * (body - 1) + axis] * action_scale(body, axis);
}

}  // namespace olympics::client::smpl
