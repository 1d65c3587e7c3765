// The scripted boxer's straight punch on the control toolkit: arm inverse kinematics puts the
// glove's centre on a point through the target with its knuckle face (the side away from the
// wrist) turned along the line from the shoulder, and the drives carry the arm there from the
// guard with gravity compensation for the glove. A blow scores only when the glove arrives
// fast and knuckles first (sports/boxing/blows.h), so the punch aims *through* the target:
// the arm is still extending when the glove meets it.
#pragma once

#include <Eigen/Core>
#include <array>
#include <span>

#include "arm_control.h"
#include "control/body_model.h"
#include "control/limb_control.h"

namespace olympics::client {

class BoxingPunch {
 public:
  // `trunk`: the spine and chest lean and turn the shoulder toward the target as well.
  explicit BoxingPunch(bool trunk = false);
  BoxingPunch(const BoxingPunch&) = delete;  // the arms hold on to the model
  BoxingPunch& operator=(const BoxingPunch&) = delete;

  // Drives `arm` to hit `target` (heading frame, from the root): the glove aimed `through`
  // metres beyond it along the line from the shoulder.
  void throw_at(std::span<const float> observation, std::span<float> action, Arm arm,
                const Eigen::Vector3d& target, double through);
  // The next punch solves from the observed arm (a guard in between).
  void reset();
  // The glove's centre as the observation shows it (heading frame), for reach checks.
  Eigen::Vector3d glove(std::span<const float> observation, Arm arm) const;
  // How far the glove's centre reaches from the shoulder with the arm straight.
  double reach(Arm arm) const { return arms_[index(arm)].ik().reach(); }

 private:
  static int index(Arm arm) { return arm == Arm::Right ? 1 : 0; }
  control::BodyModel model_;  // the boxer, both gloves on (the server's own model)
  std::array<control::LimbControl, 2> arms_;
};

}  // namespace olympics::client
