#include "control/leg_support.h"

#include <algorithm>
#include <cmath>

#include "control/drive_target.h"
#include "core/self_observation_layout.h"

namespace olympics::client::control {
namespace {

constexpr int kHip[2] = {1, 5};  // left, right: hip, knee, ankle follow
constexpr double kGravity = 9.81;

// Hip to ankle at rest: the parallelogram's arm.
double leg_length(const BodyModel& model, int leg) {
  return (model.body(kHip[leg] + 1).offset + model.body(kHip[leg] + 2).offset).norm();
}

// The torque on the leg below `joint` (its parent's frame) from gravity on that leg and the
// ground's vertical force `newtons` at `on_ground` (heading frame): what the joint's drive holds.
Eigen::Vector3d load_below(const BodyModel& model, const BodyPose& pose, int joint,
                           const Eigen::Vector3d& on_ground, double newtons) {
  const Eigen::Vector3d ground =
      (on_ground - pose.position[joint]).cross(Eigen::Vector3d(0, 0, newtons));
  const Eigen::Matrix3d& parent = pose.rotation[model.body(joint).parent];
  return model.gravity_torque(pose, joint) + parent.transpose() * ground;
}

}  // namespace

Eigen::Vector3d foot_centre(const BodyModel& model, const BodyPose& pose, bool left) {
  const int ankle = kHip[left ? 0 : 1] + 2;
  return pose.position[ankle] + pose.rotation[ankle] * model.body(ankle).com;
}

Eigen::Vector3d centre_of_mass_velocity(const BodyModel& model,
                                        std::span<const float> observation) {
  const core::SelfObservationLayout layout{model.size()};
  Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
  for (int b = 0; b < model.size(); ++b) {
    const int at = layout.linear_velocity(b);
    momentum += model.body(b).mass *
                Eigen::Vector3d(observation[at], observation[at + 1], observation[at + 2]);
  }
  return momentum / model.total_mass();
}

void hold_on_legs(const BodyModel& model, const BodyPose& pose, const Eigen::Vector3d& com_velocity,
                  const LegSupport& support, std::span<float> action, const LegSupportGains& g) {
  const double left = std::clamp(support.left_share, 0.0, 1.0);
  const double share[2] = {left, 1 - left};
  const double both = 2 * std::min(left, 1 - left);  // 1 shared evenly, 0 on one foot
  Eigen::Vector3d ankles[2], feet[2];
  for (int leg = 0; leg < 2; ++leg) {
    ankles[leg] = pose.position[kHip[leg] + 2];
    feet[leg] = ankles[leg] + g.foot_point * (foot_centre(model, pose, leg == 0) - ankles[leg]);
  }
  const Eigen::Vector3d com = model.centre_of_mass(pose);
  const Eigen::Vector3d& v = com_velocity;
  // The centre of mass's place: sideways at the share's point between the feet, forward `ahead`
  // of the loaded ankles.
  const double side = share[0] * feet[0].y() + share[1] * feet[1].y();
  const double forward = share[0] * ankles[0].x() + share[1] * ankles[1].x() + g.ahead;
  const double across = feet[0].y() - feet[1].y();
  // The parallelogram's roll (positive carries the pelvis right, -y): planned from the share's
  // displacement from the middle, corrected by the centre of mass's error.
  const double planned = (left - 0.5) * across;
  const double carried = -std::asin(std::clamp(planned / leg_length(model, 0), -0.5, 0.5));
  const double correction =
      (1 - (1 - g.both_feet_scale) * both) *
      (g.side_p * (com.y() - side) + g.side_d * (v.y() - support.left_share_rate * across));
  // Each ankle's planned place forward from the share's point between them, and the centre of
  // mass's planned velocity forward: the share's rate times the feet's stagger.
  const double planned_x[2] = {share[1] * support.left_ahead, -share[0] * support.left_ahead};
  const double forward_push = g.forward_p * (com.x() - forward) +
                              g.forward_d * (v.x() - support.left_share_rate * support.left_ahead);
  const Eigen::Vector3d up = pose.rotation[0].col(2);
  const double weight = model.total_mass() * kGravity;
  const auto hip_yaw = [&](int hip) {  // where the hip is about its yaw axis
    return euler_xyz(pose.rotation[0].transpose() * pose.rotation[hip]).z();
  };
  for (int leg = 0; leg < 2; ++leg) {
    const double w = support.half_and_half ? 0.5 : share[leg];
    // Where this foot's share of the ground's force acts: under the centre of mass forward (the
    // ankle's pitch holds the body's lean; with one foot ahead, as far ahead of it as the foot is
    // planned), and sideways as far off the foot's point as the centre of mass is off its place
    // (the shares' forces then hold the body where it is).
    const Eigen::Vector3d on_ground(com.x() + planned_x[leg], feet[leg].y() + com.y() - side,
                                    feet[leg].z());
    const double tilt = std::asin(std::clamp(planned_x[leg] / leg_length(model, leg), -0.5, 0.5));
    // The free foot raised by flexing hip and knee alike (the shank stays vertical).
    const double thigh_and_shank =
        model.body(kHip[leg] + 1).offset.norm() + model.body(kHip[leg] + 2).offset.norm();
    const double lift = std::acos(std::clamp(1 - support.lift[leg] / thigh_and_shank, 0.0, 1.0));
    for (int k = 0; k < 3; ++k) {  // hip, knee, ankle
      const int joint = kHip[leg] + k;
      Eigen::Vector3d held = load_below(model, pose, joint, on_ground, w * weight);
      if (support.half_and_half) held.x() = 0;
      Eigen::Vector3d torque = -g.compensation * held;  // the drive's, on the leg below
      Eigen::Vector3d angles = Eigen::Vector3d::Zero();
      if (k == 0) {
        torque.y() -= w * g.upright * up.x();
        torque.x() += w * g.upright * up.y();
        // On one foot the loaded hip levels the pelvis and the free one hangs its leg; the signs
        // are the measured ones (the other signs fell on every tuning seed).
        const double level = (1 - both) * (w * g.stance_level - (1 - w) * g.swing_level);
        angles = {carried + both * correction + level * up.y(), -lift - tilt, 0};
        // A leg (almost) unloaded: its hip's yaw target follows where the hip is, so the leg does
        // not twist the foot it puts down (and the body on the other foot) back to the pelvis's
        // heading; its stiffness returns as the leg takes the weight.
        if (w < g.free_hip_yaw_below) angles.z() = (1 - w / g.free_hip_yaw_below) * hip_yaw(joint);
      } else if (k == 1) {
        angles = {0, 2 * lift, 0};
      } else {
        torque.y() += w * forward_push;
        angles = {-(carried + correction), tilt - lift, 0};
      }
      const Eigen::Vector3d& kp = model.body(joint).kp;
      const Eigen::Vector3d offset(torque.x() / kp.x(), torque.y() / kp.y(), torque.z() / kp.z());
      write_joint(action, joint, exp_rotation(offset) * from_euler_xyz(angles));
    }
  }
}

}  // namespace olympics::client::control
