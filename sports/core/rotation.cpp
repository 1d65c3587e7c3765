#include "core/rotation.h"

#include <cmath>

namespace olympics::core {

double heading_angle(const Eigen::Quaterniond& root) {
  Eigen::Vector3d forward = root * Eigen::Vector3d::UnitX();
  return std::atan2(forward.y(), forward.x());
}

Eigen::Quaterniond inverse_heading(const Eigen::Quaterniond& root) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(-heading_angle(root), Eigen::Vector3d::UnitZ()));
}

Eigen::Vector3d rotation_vector(const Eigen::Quaterniond& q_in) {
  Eigen::Quaterniond q = q_in.normalized();
  if (q.w() < 0) q.coeffs() = -q.coeffs();  // shortest way round
  double s = q.vec().norm();
  if (s < 1e-12) return 2.0 * q.vec();  // small-angle limit
  double angle = 2.0 * std::atan2(s, q.w());
  return q.vec() * (angle / s);
}

}  // namespace olympics::core
