#include "control/drive_target.h"

#include <algorithm>
#include <cmath>

#include "smpl_observation.h"
#include "smplx_observation.h"

namespace olympics::client::control {

Eigen::Vector3d euler_xyz(const Eigen::Matrix3d& r) {
  const double b = std::asin(std::clamp(r(0, 2), -1.0, 1.0));
  return {std::atan2(-r(1, 2), r(2, 2)), b, std::atan2(-r(0, 1), r(0, 0))};
}

Eigen::Matrix3d from_euler_xyz(const Eigen::Vector3d& a) {
  return (Eigen::AngleAxisd(a.x(), Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(a.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(a.z(), Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

Eigen::Matrix3d exp_rotation(const Eigen::Vector3d& v) {
  const double angle = v.norm();
  if (angle < 1e-12) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, v / angle).toRotationMatrix();
}

Eigen::Vector3d log_rotation(const Eigen::Matrix3d& r) {
  const Eigen::AngleAxisd aa(r);
  return aa.angle() * aa.axis();
}

Eigen::Matrix3d drive_target(const ModelBody& body, const Eigen::Matrix3d& desired,
                             const Eigen::Vector3d& held, const Eigen::Vector3d& velocity) {
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
    if (body.kp[k] > 0) offset[k] = (body.kd[k] * velocity[k] - held[k]) / body.kp[k];
  return exp_rotation(offset) * desired;
}

// An SMPL-X action (153 targets) has its own scales per joint; an SMPL one (69) scales by pi.
void write_joint(std::span<float> action, int body, const Eigen::Matrix3d& target) {
  const Eigen::Vector3d a = euler_xyz(target);
  const bool smplx = action.size() == smplx::kActions;
  for (int axis = 0; axis < 3; ++axis)
    smplx ? smplx::set_joint(action, body, axis, a[axis])
          : smpl::set_joint(action, body, axis, a[axis]);
}

Eigen::Matrix3d read_joint(std::span<const float> action, int body) {
  Eigen::Vector3d a;
  const bool smplx = action.size() == smplx::kActions;
  for (int axis = 0; axis < 3; ++axis)
    a[axis] =
        smplx ? smplx::joint_angle(action, body, axis) : smpl::joint_angle(action, body, axis);
  return from_euler_xyz(a);
}

}  // namespace olympics::client::control
