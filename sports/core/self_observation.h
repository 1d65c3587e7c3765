// The humanoid's self observation (HUMANOID.md section 2), in the root's heading frame.
//
// Its fields for B bodies (SMPL B = 24 -> 358 floats; SMPL-X B = 52 -> 778) are described once,
// for the server and the clients alike, in core/self_observation_layout.h. Every vector is
// rotated by the inverse root heading (yaw only); every entry is clamped to +-5.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/humanoid.h"

namespace olympics::core {

constexpr float kObservationClamp = 5.0f;

int self_observation_size(int body_count);
void write_self_observation(const std::vector<BodyState>& bodies, std::span<float> out);
// "root_height", "pos.L_Hip.x", ..., for describe commands and documentation.
std::vector<std::string> self_observation_names(const ModelSpec& spec);

}  // namespace olympics::core
