#include "control/standing_jump.h"

#include <algorithm>
#include <stdexcept>

#include "control/minimum_jerk.h"
#include "smpl_observation.h"

namespace olympics::client::control {
namespace {

using namespace smpl;

constexpr int kPoseParameters = 6;

JumpPose pose_from(std::span<const double> x) { return {x[0], x[1], x[2], x[3], x[4], x[5]}; }

void pose_to(const JumpPose& p, std::span<double> x) {
  x[0] = p.hip, x[1] = p.knee, x[2] = p.ankle, x[3] = p.trunk, x[4] = p.arm_x, x[5] = p.arm_z;
}

JumpPose blend(const JumpPose& a, const JumpPose& b, double s) {
  auto mix = [s](double u, double v) { return u + s * (v - u); };
  return {mix(a.hip, b.hip),     mix(a.knee, b.knee),   mix(a.ankle, b.ankle),
          mix(a.trunk, b.trunk), mix(a.arm_x, b.arm_x), mix(a.arm_z, b.arm_z)};
}

void write_pose(const JumpPose& p, std::span<float> a) {
  for (int hip : {kLHip, kRHip}) {
    set_joint(a, hip, 0, 0);
    set_joint(a, hip, 1, p.hip);
    set_joint(a, hip, 2, 0);
    set_joint(a, hip + 1, 1, p.knee);
    set_joint(a, hip + 2, 1, p.ankle);
  }
  for (int trunk : {int{kTorso}, 10, int{kChest}}) set_joint(a, trunk, 1, p.trunk);
  // The left arm lies along +y, the right along -y: the same motion is mirrored.
  set_joint(a, kLShoulder, 0, -p.arm_x);
  set_joint(a, kLShoulder, 2, -p.arm_z);
  set_joint(a, kRShoulder, 0, p.arm_x);
  set_joint(a, kRShoulder, 2, p.arm_z);
}

}  // namespace

StandingJump StandingJump::from(std::span<const double> x) {
  if (x.size() != kParameters)
    throw std::invalid_argument("a standing jump has 20 parameters: 3 poses of 6, then 2 times");
  StandingJump j;
  j.crouch = pose_from(x.subspan(0, kPoseParameters));
  j.push = pose_from(x.subspan(kPoseParameters, kPoseParameters));
  j.flight = pose_from(x.subspan(2 * kPoseParameters, kPoseParameters));
  j.crouch_s = std::clamp(x[18], 0.15, 1.5);
  j.push_s = std::clamp(x[19], 0.03, 0.6);
  return j;
}

void StandingJump::to(std::span<double> x) const {
  if (x.size() != kParameters)
    throw std::invalid_argument("a standing jump has 20 parameters: 3 poses of 6, then 2 times");
  pose_to(crouch, x.subspan(0, kPoseParameters));
  pose_to(push, x.subspan(kPoseParameters, kPoseParameters));
  pose_to(flight, x.subspan(2 * kPoseParameters, kPoseParameters));
  x[18] = crouch_s, x[19] = push_s;
}

void write_standing_jump(const StandingJump& j, double t, std::span<float> a) {
  if (t < j.crouch_s)
    write_pose(blend(JumpPose{}, j.crouch, minimum_jerk(t / j.crouch_s)), a);
  else if (t < j.crouch_s + j.push_s)
    write_pose(j.push, a);
  else
    write_pose(j.flight, a);
}

}  // namespace olympics::client::control
