#include "scripted_tennis_swing.h"

#include <algorithm>

#include "control/drive_target.h"
#include "smpl_observation.h"

namespace olympics::client {

SwingTurn swing_turn(double tau, double rate, double back, double follow) {
  if (rate <= 0) return {-back, 0};
  // From rest at -back to `rate` at zero at a constant acceleration: it takes 2 back / rate.
  const double lasts = 2 * back / rate;
  if (tau <= -lasts) return {-back, 0};
  if (tau <= 0) {
    const double accel = rate / lasts, since = tau + lasts;
    return {-back + 0.5 * accel * since * since, accel * since, accel};
  }
  if (rate * tau >= follow) return {follow, 0};
  return {rate * tau, rate};
}

void drive_turned_arm(const control::BodyModel& model, const control::LimbIk& ik,
                      const control::BodyPose& pose, const std::vector<Eigen::Matrix3d>& contact,
                      const SwingTurn& turn, double gravity_scale, std::span<float> action,
                      bool hold_turning) {
  const auto& joints = ik.joints();
  // The vertical (the heading frame's z) in the shoulder's parent frame: a turn about it there
  // turns everything below the shoulder about the shoulder's vertical.
  const int shoulder = joints[0].body;
  const Eigen::Matrix3d parent = pose.rotation[model.body(shoulder).parent];
  const Eigen::Vector3d up = parent.transpose() * Eigen::Vector3d::UnitZ();
  std::vector<Eigen::Matrix3d> relative = model.relative_rotations(pose);
  for (size_t k = 0; k < joints.size(); ++k) relative[joints[k].body] = contact[k];
  relative[shoulder] = Eigen::AngleAxisd(turn.angle, up).toRotationMatrix() * contact[0];
  const control::BodyPose wanted = model.forward(relative);
  for (size_t k = 0; k < joints.size(); ++k) {
    const int b = joints[k].body;
    const Eigen::Vector3d velocity =
        k == 0 ? Eigen::Vector3d(turn.rate * up) : Eigen::Vector3d::Zero();
    Eigen::Vector3d held = gravity_scale * model.gravity_torque(wanted, b);
    if (hold_turning)
      held +=
          model.turning_torque(wanted, b, wanted.position[shoulder], turn.rate, turn.acceleration);
    control::write_joint(action, b,
                         control::drive_target(model.body(b), relative[b], held, velocity));
  }
}

void drive_counter_arm(const control::BodyModel& model, const control::BodyPose& pose,
                       const SwingTurn& turn, double gravity_scale, std::span<float> action) {
  const int shoulder = smpl::kLShoulder;
  const auto& body = model.body(shoulder);
  const Eigen::Vector3d up = pose.rotation[body.parent].transpose() * Eigen::Vector3d::UnitZ();
  // Out to the side is the rest posture (every action zero); turned by -angle about the vertical.
  const Eigen::Matrix3d wanted = Eigen::AngleAxisd(-turn.angle, up).toRotationMatrix();
  const Eigen::Vector3d held = gravity_scale * model.gravity_torque(pose, shoulder);
  control::write_joint(action, shoulder,
                       control::drive_target(body, wanted, held, Eigen::Vector3d(-turn.rate * up)));
}

}  // namespace olympics::client
