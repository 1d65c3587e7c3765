// A rule piece: where a player starts, moved by up to 0.1 m in x and y and turned by up to
// 0.1 rad by the match's random stream, so that seeds differ (fencing, boxing, soccer).
#pragma once

#include <Eigen/Core>
#include <random>

#include "core/humanoid.h"

namespace olympics::sports {

inline core::RootPlacement jittered_start(const Eigen::Vector2d& at, double yaw,
                                          std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  const double along = u(rng), across = u(rng), turn = u(rng);
  return {{at.x() + 0.1 * along, at.y() + 0.1 * across, 0}, yaw + 0.1 * turn};
}

}  // namespace olympics::sports
