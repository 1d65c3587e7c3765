// Reading the SMPL-X self observation (778 floats, 52 bodies) and writing SMPL-X actions (153 PD
// targets): offsets, body indices and the action scales. The offsets come from the one
// description of the self observation's fields that the server writes it by
// (sports/core/self_observation_layout.h).
#pragma once

#include <Eigen/Core>
#include <span>

#include "self_observation_layout.h"

namespace olympics::client::smplx {

constexpr int kBodies = 52;
constexpr core::SelfObservationLayout kSelf{kBodies};
constexpr int kSelfObservation = kSelf.size();      // 778
constexpr int kActions = 3 * (kBodies - 1);         // 153: x, y, z hinges per joint
constexpr int kBodyPos = kSelf.body_positions();    // bodies 1..51 relative to the root
constexpr int kRotations = kSelf.body_rotations();  // (x axis, z axis) per body
constexpr int kLinVel = kSelf.linear_velocities();  // per body, the root first

// Body indices (HUMANOID-SMPLX.md section 1): the SMPL body's first 14, then each arm's thorax,
// shoulder, elbow and wrist (the palm) and its 15 finger links (index, middle, pinky, ring, thumb;
// 3 links each). Joint j moves body j (j >= 1).
enum Body {
  kLHip = 1,
  kLKnee = 2,
  kLAnkle = 3,
  kRHip = 5,
  kRKnee = 6,
  kRAnkle = 7,
  kTorso = 9,  // the trunk's three links: torso, spine, chest
  kSpine = 10,
  kChest = 11,
  kLThorax = 14,
  kLShoulder = 15,
  kLElbow = 16,
  kLWrist = 17,
  kLFingers = 18,
  kRThorax = 33,
  kRShoulder = 34,
  kRElbow = 35,
  kRWrist = 36,
  kRFingers = 37,
};
// Of each hand's 15 finger links: the four fingers' (3 each) come first, the thumb's 3 last.
constexpr int kLinksBeforeThumb = 12;

inline Eigen::Vector3d vec3(std::span<const float> o, int at) {
  return {o[at], o[at + 1], o[at + 2]};
}
// Relative to the root, heading frame.
inline Eigen::Vector3d body_position(std::span<const float> o, int body) {
  return body == 0 ? Eigen::Vector3d::Zero() : vec3(o, kSelf.body_position(body));
}

// Body `body`'s rotation (body frame to heading frame), from its observed x and z axes.
Eigen::Matrix3d body_rotation(std::span<const float> o, int body);

// Sets joint `body`'s hinge `axis` (0 x, 1 y, 2 z) to `radians`, through the action scale the
// server applies (sports/core/action_map.h: min(1.2 x the range's bound, pi), knee flexion 5).
void set_joint(std::span<float> action, int body, int axis, double radians);
// The angle set_joint wrote.
double joint_angle(std::span<const float> action, int body, int axis);

}  // namespace olympics::client::smplx
