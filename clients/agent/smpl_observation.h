// Reading the SMPL self observation (358 floats) and writing SMPL actions (69 PD targets):
// offsets and small helpers shared by the scripted controllers. The offsets come from the one
// description of the self observation's fields that the server writes it by
// (sports/core/self_observation_layout.h), for the SMPL humanoid's 24 bodies.
#pragma once

#include <Eigen/Core>
#include <span>

#include "self_observation_layout.h"

namespace olympics::client::smpl {

constexpr int kBodies = 24;
constexpr core::SelfObservationLayout kSelf{kBodies};
constexpr int kSelfObservation = kSelf.size();      // 358
constexpr int kActions = 3 * (kBodies - 1);         // 69: x, y, z hinges per joint
constexpr int kBodyPos = kSelf.body_positions();    // bodies 1..23 relative to the root
constexpr int kRotations = kSelf.body_rotations();  // (x axis, z axis) per body
constexpr int kLinVel = kSelf.linear_velocities();  // per body, the root first

// Body indices (HUMANOID.md section 1.1). Joint j moves body j (j >= 1).
enum Body {
  kPelvis = 0,
  kLHip = 1,
  kLKnee = 2,
  kLAnkle = 3,
  kLToe = 4,
  kRHip = 5,
  kRKnee = 6,
  kRAnkle = 7,
  kRToe = 8,
  kTorso = 9,
  kChest = 11,
  kHead = 13,
  kLThorax = 14,
  kLShoulder = 15,
  kLElbow = 16,
  kLHand = 18,
  kRThorax = 19,
  kRShoulder = 20,
  kRElbow = 21,
  kRHand = 23,
};

inline Eigen::Vector3d vec3(std::span<const float> o, int at) {
  return {o[at], o[at + 1], o[at + 2]};
}
inline Eigen::Vector3d body_position(std::span<const float> o, int body) {
  return body == kPelvis ? Eigen::Vector3d::Zero() : vec3(o, kSelf.body_position(body));
}
inline double root_height(std::span<const float> o) { return o[kSelf.root_height()]; }
inline Eigen::Vector3d root_velocity(std::span<const float> o) {
  return vec3(o, kSelf.linear_velocity(kPelvis));
}

// The body's rotation in the heading frame, rebuilt from its x and z axes.
Eigen::Matrix3d body_rotation(std::span<const float> o, int body);

// Sets joint `body`'s hinge `axis` (0 x, 1 y, 2 z) to `radians`: a = radians / pi, knee flexion
// a = radians / 5 (HUMANOID.md: PD target = pi a per axis, knee flexion 5 a).
void set_joint(std::span<float> action, int body, int axis, double radians);
// The angle set_joint wrote.
double joint_angle(std::span<const float> action, int body, int axis);

}  // namespace olympics::client::smpl
