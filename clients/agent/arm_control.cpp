#include "arm_control.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "smpl_observation.h"

namespace olympics::client {

using namespace smpl;

void set_ball_joint(std::span<float> a, int body, const Eigen::Quaterniond& q) {
  const Eigen::Vector3d xyz = q.toRotationMatrix().eulerAngles(0, 1, 2);
  for (int axis = 0; axis < 3; ++axis) set_joint(a, body, axis, xyz[axis]);
}

void point_arm(std::span<const float> o, std::span<float> a, Arm arm,
               const Eigen::Vector3d& direction, double roll) {
  const bool right = arm == Arm::Right;
  Eigen::Vector3d d = body_rotation(o, right ? kRThorax : kLThorax).transpose() * direction;
  if (d.norm() < 1e-9) d = Eigen::Vector3d(1, 0, 0);
  d.normalize();
  const Eigen::Vector3d rest(0, right ? -1 : 1, 0);
  const Eigen::Quaterniond aim = Eigen::Quaterniond::FromTwoVectors(rest, d);
  set_ball_joint(a, right ? kRShoulder : kLShoulder, Eigen::AngleAxisd(roll, d) * aim);
}

void bend_elbow(std::span<float> a, Arm arm, double radians) {
  const bool right = arm == Arm::Right;
  const int elbow = right ? kRElbow : kLElbow;
  set_joint(a, elbow, 0, 0);
  set_joint(a, elbow, 1, 0);
  set_joint(a, elbow, 2, right ? radians : -radians);
}

const Eigen::Vector3d& ArmDirection::follow(const Eigen::Vector3d& wanted, double rate, double dt) {
  if (wanted.norm() < 1e-9) return direction_;
  const Eigen::Vector3d w = wanted.normalized();
  const double angle = std::acos(std::clamp(direction_.dot(w), -1.0, 1.0));
  const double step = rate * dt;
  if (angle <= step) {
    direction_ = w;
  } else {
    Eigen::Vector3d axis = direction_.cross(w);
    if (axis.norm() < 1e-9) axis = Eigen::Vector3d::UnitZ();  // opposite: turn about the vertical
    direction_ = (Eigen::AngleAxisd(step, axis.normalized()) * direction_).normalized();
  }
  return direction_;
}

}  // namespace olympics::client
