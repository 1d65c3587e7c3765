// Where a fencer or a boxer starts: on the x axis, `distance` from the centre on its side
// (player 0 at -x facing +x, player 1 at +x facing -x), jittered (framework/jittered_start.h).
#pragma once

#include "framework/jittered_start.h"

namespace olympics::sports::combat {

inline int side(int player) { return player == 0 ? -1 : 1; }

inline core::RootPlacement jittered_start(int player, double distance, std::mt19937_64& rng) {
  return sports::jittered_start({side(player) * distance, 0}, player == 0 ? 0.0 : M_PI, rng);
}

}  // namespace olympics::sports::combat
