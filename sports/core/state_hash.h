// A hash of a scene's complete body state, bit for bit: replays compare it to prove that a
// re-run reproduced the recorded match exactly.
#pragma once

#include <cstdint>

#include "core/humanoid_scene.h"

namespace olympics::core {

std::uint64_t state_hash(const HumanoidScene& scene);

}  // namespace olympics::core
