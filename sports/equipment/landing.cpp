#include "equipment/landing.h"

#include <algorithm>
#include <cmath>

namespace olympics::sports::equipment {

Eigen::Vector2d predict_landing(const Eigen::Vector3d& p0, const Eigen::Vector3d& v0, double h,
                                double g) {
  const double disc = v0.z() * v0.z() + 2 * g * (p0.z() - h);
  const double t = disc >= 0 ? (v0.z() + std::sqrt(disc)) / g : std::max(v0.z(), 0.0) / g;
  return {p0.x() + v0.x() * t, p0.y() + v0.y() * t};
}

}  // namespace olympics::sports::equipment
