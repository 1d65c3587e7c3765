#include "control/limb_control.h"

#include "control/drive_target.h"

namespace olympics::client::control {

const LimbSolution& LimbControl::drive(const BodyPose& pose, const LimbGoal& now,
                                       const LimbGoal& next, double tick_s, std::span<float> action,
                                       bool compensate) {
  LimbSolution at = ik_.solve(pose, now, last_.relative);
  const LimbSolution then = ik_.solve(pose, next, at.relative, 10);
  // The wanted pose: the limb as solved, the rest as observed; its weight from there.
  std::vector<Eigen::Matrix3d> relative = model_.relative_rotations(pose);
  const auto& joints = ik_.joints();
  for (size_t k = 0; k < joints.size(); ++k) relative[joints[k].body] = at.relative[k];
  const BodyPose wanted = model_.forward(relative);
  for (size_t k = 0; k < joints.size(); ++k) {
    const int b = joints[k].body;
    const Eigen::Vector3d velocity =
        log_rotation(then.relative[k] * at.relative[k].transpose()) / tick_s;
    const Eigen::Vector3d held =
        compensate ? Eigen::Vector3d(gravity_scale_ * model_.gravity_torque(wanted, b))
                   : Eigen::Vector3d::Zero();
    write_joint(action, b, drive_target(model_.body(b), at.relative[k], held, velocity));
  }
  last_ = std::move(at);
  return last_;
}

void hold_against_gravity(const BodyModel& model, const BodyPose& pose, std::span<const int> bodies,
                          std::span<float> action, double gravity_scale) {
  for (int b : bodies)
    write_joint(action, b,
                drive_target(model.body(b), Eigen::Matrix3d::Identity(),
                             gravity_scale * model.gravity_torque(pose, b)));
}

void hold_standing_legs(const BodyModel& model, const BodyPose& pose, std::span<float> action,
                        double gravity_scale) {
  static constexpr int kLegJoints[] = {1, 2, 3, 5, 6, 7};  // SMPL hips, knees, ankles
  for (int b : kLegJoints)
    write_joint(action, b,
                drive_target(model.body(b), read_joint(action, b),
                             -0.5 * gravity_scale * model.gravity_torque_above(pose, b)));
}

}  // namespace olympics::client::control
