// A hash of a scene's complete body state, bit for bit: replays compare it to prove that a
// re-run reproduced the recorded match exactly.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/humanoid_scene.h"

namespace olympics::core {

// Appends an ODE body's complete state: position (3), quaternion (4), linear and angular
// velocity (3 + 3).
void append_body_state(dBodyID body, std::vector<double>& values);

// `extra` values (e.g. a ball flown outside ODE) are hashed after the bodies.
std::uint64_t state_hash(const HumanoidScene& scene, std::span<const double> extra = {});

}  // namespace olympics::core
