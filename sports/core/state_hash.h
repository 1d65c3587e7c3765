// A hash of a scene's complete body state, bit for bit: replays compare it to prove that a
// re-run reproduced the recorded match exactly.
#pragma once

#include <cstdint>
#include <span>

#include "core/humanoid_scene.h"

namespace olympics::core {

// `extra` values (e.g. a ball flown outside ODE) are hashed after the bodies.
std::uint64_t state_hash(const HumanoidScene& scene, std::span<const double> extra = {});

}  // namespace olympics::core
