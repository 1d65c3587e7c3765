// What fencers and boxers see of their opponent, as observation blocks after the self
// observation (heading frame, relative to the root):
//
//   opponent_root     6  its root position (3) and velocity (3)    fields position, velocity
//   opponent_heading  2  cos, sin of its heading relative to mine  fields cos, sin
//   opponent_targets 15  positions of its pelvis, torso, spine,    fields pelvis, torso, spine,
//                        chest and head                                   chest, head
#pragma once

#include <array>
#include <span>
#include <vector>

#include "core/humanoid.h"
#include "framework/heading_frame.h"
#include "framework/observation_writer.h"
#include "sport.h"

namespace olympics::sports::combat {

// The bodies a touch or a punch scores on (SPORTS.md; the seed's targets).
inline constexpr std::array<const char*, 5> kTargetBodies = {"Pelvis", "Torso", "Spine", "Chest",
                                                             "Head"};
// Their fields in the block opponent_targets, in the same order.
inline constexpr std::array<const char*, 5> kTargetFields = {"pelvis", "torso", "spine", "chest",
                                                             "head"};
// Their indices in a model; throws std::invalid_argument if one is missing.
std::vector<int> target_body_indices(const core::ModelSpec& spec);

std::vector<LayoutBlock> opponent_blocks();
void write_opponent_blocks(const HeadingFrame& frame, const core::Humanoid& opponent,
                           std::span<const int> target_bodies, ObservationWriter& out);

// A point on a body (in its frame), and its velocity, in the world.
struct PointState {
  Eigen::Vector3d position, velocity;
};
PointState point_on_body(const core::BodyState& body, const Eigen::Vector3d& local);

}  // namespace olympics::sports::combat
