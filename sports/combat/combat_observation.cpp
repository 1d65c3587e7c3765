#include "combat/combat_observation.h"

#include <cmath>
#include <stdexcept>

#include "core/rotation.h"

namespace olympics::sports::combat {

std::vector<int> target_body_indices(const core::ModelSpec& spec) {
  std::vector<int> out;
  for (const char* name : kTargetBodies) {
    const int i = spec.body_index(name);
    if (i < 0)
      throw std::invalid_argument(spec.source + ": no body \"" + name + "\" to be a target");
    out.push_back(i);
  }
  return out;
}

std::vector<LayoutBlock> opponent_blocks() {
  std::vector<FieldSize> targets;
  for (const char* target : kTargetFields) targets.push_back({target, 3});
  return {LayoutBlock::of(
              "opponent_root", "m, m/s",
              "opponent's root position (3) and velocity (3), heading frame, relative to the root",
              {{"position", 3}, {"velocity", 3}}),
          LayoutBlock::of("opponent_heading", "cos, sin", "opponent's heading relative to mine",
                          {{"cos", 1}, {"sin", 1}}),
          LayoutBlock::of("opponent_targets", "m",
                          "opponent's pelvis, torso, spine, chest and head positions, heading "
                          "frame",
                          targets)};
}

void write_opponent_blocks(const HeadingFrame& frame, const core::Humanoid& opponent,
                           std::span<const int> target_bodies, ObservationWriter& out) {
  const core::BodyState root = opponent.body_state(0);
  out.begin("opponent_root")
      .field("position")
      .put(frame.point(root.position))
      .field("velocity")
      .put(frame.vector(root.linear_velocity));
  const double relative =
      core::heading_angle(root.orientation) - core::heading_angle(frame.root.orientation);
  out.begin("opponent_heading")
      .field("cos")
      .put(std::cos(relative))
      .field("sin")
      .put(std::sin(relative));
  out.begin("opponent_targets");
  for (size_t k = 0; k < target_bodies.size(); ++k)
    out.field(kTargetFields[k]).put(frame.point(opponent.body_state(target_bodies[k]).position));
}

PointState point_on_body(const core::BodyState& body, const Eigen::Vector3d& local) {
  const Eigen::Vector3d arm = body.orientation * local;
  return {body.position + arm, body.linear_velocity + body.angular_velocity.cross(arm)};
}

}  // namespace olympics::sports::combat
