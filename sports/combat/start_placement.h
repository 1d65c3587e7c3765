// Where a fencer or a boxer starts: on the x axis, `distance` from the centre on its side
// (player 0 at -x facing +x, player 1 at +x facing -x), moved by up to 0.1 m along and across
// and turned by up to 0.1 rad by the match's random stream, so that seeds differ.
#pragma once

#include <random>

#include "core/humanoid.h"

namespace olympics::sports::combat {

inline int side(int player) { return player == 0 ? -1 : 1; }

inline core::RootPlacement jittered_start(int player, double distance, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  const double along = u(rng), across = u(rng), turn = u(rng);
  return {{side(player) * distance + 0.1 * along, 0.1 * across, 0},
          (player == 0 ? 0.0 : M_PI) + 0.1 * turn};
}

}  // namespace olympics::sports::combat
