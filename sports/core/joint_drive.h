// Implicit PD drive of one 3-DoF joint (a ball joint plus an ODE angular motor).
//
// Why this scheme (measured, see docs/physics.md): explicit PD torques with SMPL gains blow up
// at policy-sized steps, and per-axis Euler motors lock at 90 degrees. Here the joint error is
// the rotation vector of (current relative rotation) * (target)^-1, expressed on the parent's
// x, y, z axes; an angular motor in user mode holds a stop at zero error on each axis with
// StopERP = h kp / (h kp + kd) and StopCFM = 1 / (h kp + kd), which is exactly a spring kp and
// damper kd integrated implicitly by the constraint solver. It has no gimbal lock and is stable
// for any gain at any step.
#pragma once

#include <ode/ode.h>

#include <Eigen/Geometry>
#include <array>

#include "core/model_spec.h"

namespace olympics::core {

class JointDrive {
 public:
  JointDrive(dWorldID world, dBodyID parent, dBodyID child, const Eigen::Vector3d& anchor_world,
             const BodySpec& spec);

  // Hinge angles (radians), applied in the body's hinge order (MuJoCo composition).
  void set_targets(const double* hinge_angles);
  // Before each physics step of h seconds: current error into the motor, gains into ERP/CFM.
  void prepare_step(double h);
  // Relative rotation error (rotation vector, parent frame) the last prepare_step saw.
  const Eigen::Vector3d& last_error() const { return error_; }

 private:
  dBodyID parent_, child_;
  dJointID ball_, motor_;
  Eigen::Quaterniond rest_;  // child frame relative to the parent at zero hinge angles
  std::array<Eigen::Vector3d, 3> hinge_axes_;
  std::array<double, 3> kp_{}, kd_{};
  Eigen::Quaterniond target_;  // desired child-relative-to-parent rotation
  Eigen::Vector3d error_ = Eigen::Vector3d::Zero();
  double gains_for_h_ = -1;  // step size the ERP/CFM were computed for
};

}  // namespace olympics::core
