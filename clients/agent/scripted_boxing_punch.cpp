#include "scripted_boxing_punch.h"

#include "boxing/boxing_match.h"
#include "boxing/gloves.h"
#include "control/smpl_limbs.h"
#include "smpl_observation.h"

namespace olympics::client {
namespace {

using namespace smpl;

// The left arm: the right arm's joints mirrored in the body's middle plane (y to -y), so the
// x and z Euler angles change sign.
std::vector<control::LimbJoint> smpl_left_arm() {
  std::vector<control::LimbJoint> arm = control::smpl_right_arm();
  const int left_of[] = {kLShoulder, kLElbow, kLElbow + 1, kLHand};
  for (size_t k = 0; k < arm.size(); ++k) {
    control::LimbJoint& j = arm[k];
    j.body = left_of[k];
    const Eigen::Vector3d lo = j.lo, hi = j.hi;
    j.lo = {-hi.x(), lo.y(), -hi.z()};
    j.hi = {-lo.x(), hi.y(), -lo.z()};
    j.preferred = {-j.preferred.x(), j.preferred.y(), -j.preferred.z()};
  }
  return arm;
}

std::vector<control::LimbJoint> with_trunk(std::vector<control::LimbJoint> arm, Arm side) {
  std::vector<control::LimbJoint> chain = control::smpl_right_arm_and_trunk();
  chain.resize(3);
  if (side == Arm::Left) chain[2].body = kLThorax;
  for (const auto& j : arm) chain.push_back(j);
  return chain;
}

control::LimbIk arm_ik(const control::BodyModel& model, Arm arm, bool trunk) {
  const core::ModelSpec& spec = sports::boxing::boxer_model(true);
  const int hand = arm == Arm::Right ? kRHand : kLHand;
  // The hand body's origin is the wrist: wrist -> glove centre points at the knuckles.
  const Eigen::Vector3d centre = sports::boxing::glove_centre(spec, hand);
  auto joints = arm == Arm::Right ? control::smpl_right_arm() : smpl_left_arm();
  if (trunk) joints = with_trunk(joints, arm);
  return control::LimbIk(model, joints, centre, centre.normalized());
}

}  // namespace

BoxingPunch::BoxingPunch(bool trunk)
    : model_(sports::boxing::boxer_model(true)),
      arms_{control::LimbControl(model_, arm_ik(model_, Arm::Left, trunk)),
            control::LimbControl(model_, arm_ik(model_, Arm::Right, trunk))} {}

void BoxingPunch::throw_at(std::span<const float> o, std::span<float> a, Arm arm,
                           const Eigen::Vector3d& target, double through) {
  const control::BodyPose pose = model_.pose_from_observation(o);
  const Eigen::Vector3d shoulder = pose.position[arm == Arm::Right ? kRShoulder : kLShoulder];
  const Eigen::Vector3d line = (target - shoulder).normalized();
  control::LimbGoal goal;
  goal.position = target + through * line;
  goal.axis = line;
  goal.axis_either_sign = false;
  arms_[index(arm)].drive(pose, goal, goal, 1.0 / 30, a);
}

void BoxingPunch::reset() {
  for (auto& arm : arms_) arm.reset();
}

Eigen::Vector3d BoxingPunch::glove(std::span<const float> o, Arm arm) const {
  const control::BodyPose pose = model_.pose_from_observation(o);
  const int hand = arm == Arm::Right ? kRHand : kLHand;
  return pose.position[hand] +
         pose.rotation[hand] * sports::boxing::glove_centre(sports::boxing::boxer_model(true), hand);
}

}  // namespace olympics::client
