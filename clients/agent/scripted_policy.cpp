#include "scripted_policy.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace olympics::client {
namespace {

// Observation offsets (docs/protocol.md; `olympics-server describe tennis`).
constexpr int kSelf = 358;
constexpr int kBodyPos = 1;   // 23 x 3, bodies 1..23 relative to the root, heading frame
constexpr int kLinVel = 214;  // 24 x 3, heading frame; the root first
constexpr int kBall = kSelf + 0, kBallVel = kSelf + 3, kTarget = kSelf + 12;
constexpr int kLeftAnkle = 3, kRightAnkle = 7, kRightShoulder = 20;  // body indices

// Action indices: 23 joints x (x, y, z) in body order, L_Hip first (joint j = body j + 1).
constexpr int joint(int body, int axis) { return 3 * (body - 1) + axis; }
constexpr int kLHip = 1, kRHip = 5, kLAnkle = 3, kRAnkle = 7, kRShoulder = 20, kRElbow = 21,
              kRHand = 23;

Eigen::Vector3d vec(std::span<const float> o, int at) { return {o[at], o[at + 1], o[at + 2]}; }
Eigen::Vector3d body_pos(std::span<const float> o, int body) {
  return vec(o, kBodyPos + 3 * (body - 1));
}

// Balance gains per sport (rad per m, rad per m/s, rad), found by a grid search over 12
// ball-return episodes each, scoring touches and falls: the racket's weight on the outstretched
// arm asks for other gains than the paddle's.
struct BalanceGains {
  double ankle_p, ankle_d, ankle_bias, hip_p;
};
constexpr BalanceGains kTennisBalance{1.0, 2.0, 0.0, 1.0};
constexpr BalanceGains kTableBalance{0.5, 0.5, -0.2, 2.0};

}  // namespace

void ScriptedRacketPolicy::act(std::span<const float> o, std::span<float> a) {
  if (o.size() < kSelf + 26 || a.size() != 69)
    throw std::invalid_argument(
        "the scripted policy plays tennis and table tennis (69 actions, racket observation)");
  std::fill(a.begin(), a.end(), 0.0f);
  auto set = [&](int body, int axis, double radians) {
    a[joint(body, axis)] = static_cast<float>(radians / M_PI);
  };

  const double root_height = o[0];
  const double surface = root_height + o[kTarget + 2];  // the court or table height, root-relative
  const bool table = surface > 0.3;

  // Balance: root over the middle of the ankles.
  const BalanceGains& g = table ? kTableBalance : kTennisBalance;
  const Eigen::Vector3d mid = 0.5 * (body_pos(o, kLeftAnkle) + body_pos(o, kRightAnkle));
  const Eigen::Vector3d v = vec(o, kLinVel);
  const double dx = -mid.x(), dy = -mid.y();
  for (int ankle : {kLAnkle, kRAnkle}) {
    set(ankle, 1, g.ankle_bias + g.ankle_p * dx + g.ankle_d * v.x());
    set(ankle, 0, -(g.ankle_p * dy + g.ankle_d * v.y()));
  }
  for (int hip : {kLHip, kRHip}) set(hip, 1, g.hip_p * dx);

  // Predict where the ball crosses the hitting plane x = plane in front of the root.
  const double restitution = table ? 0.9 : 0.75;
  const double plane = table ? 0.35 : 0.3;
  Eigen::Vector3d p = vec(o, kBall), bv = vec(o, kBallVel);
  const double floor_z = surface - root_height + (table ? 0.02 : 0.032);
  double t = 0;
  bool found = false;
  for (int i = 0; i < 240 && !found; ++i) {
    const double dt = 1.0 / 120;
    bv.z() -= 9.81 * dt;
    const Eigen::Vector3d next = p + bv * dt;
    if (next.z() < floor_z && bv.z() < 0) bv.z() = -restitution * bv.z();
    if ((p.x() - plane) * (next.x() - plane) <= 0 && bv.x() < 0) found = true;
    p = next;
    t += dt;
  }
  const Eigen::Vector3d shoulder = body_pos(o, kRightShoulder);
  Eigen::Vector3d aim = found ? p : Eigen::Vector3d(plane, shoulder.y() - 0.6, shoulder.z());
  // Swing: the racket waits behind the hitting point and comes through as the ball arrives.
  const double swing = found ? std::clamp(t / 0.4, 0.0, 1.0) : 1.0;
  Eigen::Vector3d d = aim - shoulder;
  if (d.norm() < 1e-6) d = Eigen::Vector3d(0, -1, 0);
  d.normalize();
  const double qz = std::asin(std::clamp(d.x(), -1.0, 1.0)) - 0.4 * swing;
  const double qx = std::atan2(-d.z(), -d.y());
  set(kRShoulder, 0, qx);
  set(kRShoulder, 2, qz);
  set(kRElbow, 0, 0);
  set(kRHand, 1, M_PI / 2);  // roll the face towards the net
}

}  // namespace olympics::client
