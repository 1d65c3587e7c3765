#include "control/standing_balance.h"

#include <algorithm>

#include "control/drive_target.h"

namespace olympics::client::control {
namespace {

constexpr int kHips[] = {1, 5};  // each leg: hip, knee, ankle follow
constexpr int kLAnkle = 3, kRAnkle = 7;
constexpr double kGravity = 9.81;

// The mass of everything not below `joint` (what it holds up standing) and its centre.
std::pair<double, Eigen::Vector3d> weight_above(const BodyModel& model, const BodyPose& pose,
                                                int joint) {
  double kg = 0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int b = 0; b < model.size(); ++b) {
    if (model.in_subtree(b, joint)) continue;
    const double m = model.body(b).mass;
    kg += m;
    centre += m * (pose.position[b] + pose.rotation[b] * model.body(b).com);
  }
  return {kg, centre / kg};
}

}  // namespace

void hold_standing_balance(const BodyModel& model, const BodyPose& pose,
                           const Eigen::Vector3d& root_velocity, std::span<float> action,
                           const StandingGains& g) {
  const Eigen::Vector3d feet = 0.5 * (pose.position[kLAnkle] + pose.position[kRAnkle]);
  const Eigen::Vector3d off = model.centre_of_mass(pose) - (feet + Eigen::Vector3d(g.ahead, 0, 0));
  const Eigen::Vector3d& v = root_velocity;
  const Eigen::Vector3d up = pose.rotation[0].col(2);
  const double roll = g.side_p * off.y() + g.side_d * v.y();
  for (int hip : kHips)
    for (int k = 0; k < 3; ++k) {  // hip, knee, ankle
      const int joint = hip + k;
      const auto [kg, centre] = weight_above(model, pose, joint);
      const double kp = model.body(joint).kp.y();
      // The weight above acts about the joint; the drive pushes the leg below the other way.
      double pitch_torque = 0.5 * kg * kGravity * (centre.x() - pose.position[joint].x());
      double roll_target = 0;
      if (k == 0) {
        pitch_torque -= 0.5 * g.upright * up.x();
        roll_target = roll + 0.5 * g.upright * up.y() / kp;
      } else if (k == 2) {
        pitch_torque += 0.5 * (g.forward_p * off.x() + g.forward_d * v.x());
        roll_target = -roll;
      }
      double pitch_target = pitch_torque / kp;
      if (k == 2) pitch_target = std::min(pitch_target, g.max_toes_down);  // + is toes down
      write_joint(action, joint, from_euler_xyz({roll_target, pitch_target, 0}));
    }
}

}  // namespace olympics::client::control
