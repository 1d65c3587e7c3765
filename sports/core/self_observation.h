// The humanoid's self observation (HUMANOID.md section 2), in the root's heading frame.
//
// Layout for B bodies (SMPL B = 24 -> 358 floats; SMPL-X B = 52 -> 778):
//   [0]                     root height
//   [1, 1+3(B-1))           positions of bodies 1..B-1 minus the root position
//   next 6B                 body rotations as tan-norm 6D (rotated x axis, then rotated z axis)
//   next 3B                 body linear velocities
//   next 3B                 body angular velocities
// Every vector is rotated by the inverse root heading (yaw only); every entry is clamped to +-5.
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
