// PD targets that make an implicit PD drive do what is wanted (sports/core/joint_drive.h).
//
// A joint's drive pulls its child toward the target with kp (per hinge axis of the parent frame)
// and damps the relative angular velocity with kd. Held against a torque tau (gravity on the
// limb below it) it settles tau / kp away from its target, and moving at w it lags (kd / kp) w
// behind it. So a controller that wants the joint AT `desired`, moving at `velocity`, asks for
//     target = exp((kd w - tau) / kp) desired
// (gravity compensation and velocity feed-forward expressed as target offsets, at the control
// rate, since a client sends targets, not torques).
#pragma once

#include <Eigen/Geometry>
#include <span>

#include "control/body_model.h"

namespace olympics::client::control {

// A loaded chain of drives is softer than its gains say: the server's iterative constraint
// solver does not converge a stiff chain in its iterations. Measured with a racket held out in
// front (tests/sports/control_toolkit_test.cpp): the face sags 6 cm where kp predicts 2, and
// compensation for three times the weight holds it within 2 cm. The default scale of gravity
// compensation, then; a player may tune its own.
inline constexpr double kLoadedDriveSoftness = 3.0;

// Euler angles (x, y, z) of R = Rx(a) Ry(b) Rz(c), with b in [-pi/2, pi/2]: the joints' hinge
// order (HUMANOID.md), so a target's three hinge angles.
Eigen::Vector3d euler_xyz(const Eigen::Matrix3d& r);
Eigen::Matrix3d from_euler_xyz(const Eigen::Vector3d& angles);
// The rotation of rotation vector v, and back.
Eigen::Matrix3d exp_rotation(const Eigen::Vector3d& v);
Eigen::Vector3d log_rotation(const Eigen::Matrix3d& r);

// The target that holds joint `body` at `desired` (relative to its parent) against `held` (the
// torque on the limb below, in the parent frame, e.g. BodyModel::gravity_torque) while it turns
// at `velocity` (relative angular velocity, parent frame).
Eigen::Matrix3d drive_target(const ModelBody& body, const Eigen::Matrix3d& desired,
                             const Eigen::Vector3d& held,
                             const Eigen::Vector3d& velocity = Eigen::Vector3d::Zero());

// Writes a joint's target rotation into an SMPL or SMPL-X action (by its size) (three hinge angles,
// set_joint scaling), and reads one back.
void write_joint(std::span<float> action, int body, const Eigen::Matrix3d& target);
Eigen::Matrix3d read_joint(std::span<const float> action, int body);

}  // namespace olympics::client::control
