// Small rotation helpers shared by control and observation code.
#pragma once

#include <Eigen/Geometry>

namespace olympics::core {

// Rotation about world z that undoes the body's heading (yaw of its x axis).
Eigen::Quaterniond inverse_heading(const Eigen::Quaterniond& root);

// Heading angle (radians) of the body's x axis projected on the ground plane.
double heading_angle(const Eigen::Quaterniond& root);

// Rotation vector (axis * angle, angle in [0, pi]) of q.
Eigen::Vector3d rotation_vector(const Eigen::Quaterniond& q);

// ODE stores rotations as w, x, y, z; Eigen's constructor takes (w, x, y, z) too.
inline Eigen::Quaterniond from_ode_quat(const double* q) {
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
}

}  // namespace olympics::core
