#include "core/joint_drive.h"

#include "core/rotation.h"

namespace olympics::core {

JointDrive::JointDrive(dWorldID world, dBodyID parent, dBodyID child,
                       const Eigen::Vector3d& anchor_world, const BodySpec& spec)
    : parent_(parent), child_(child), rest_(spec.quat), target_(spec.quat) {
  ball_ = dJointCreateBall(world, nullptr);
  dJointAttach(ball_, parent, child);
  dJointSetBallAnchor(ball_, anchor_world.x(), anchor_world.y(), anchor_world.z());

  // body1 = child, body2 = parent, so the motor's angle rate is axis . (w_child - w_parent),
  // and axes fixed to body2 stay the parent's x, y, z.
  motor_ = dJointCreateAMotor(world, nullptr);
  dJointAttach(motor_, child, parent);
  dJointSetAMotorMode(motor_, dAMotorUser);
  dJointSetAMotorNumAxes(motor_, 3);
  const dReal* r = dBodyGetRotation(parent);  // 3x4 row-major: column i is the parent's axis i
  for (int i = 0; i < 3; ++i) {
    dJointSetAMotorAxis(motor_, i, 2, r[i], r[4 + i], r[8 + i]);
    hinge_axes_[i] = spec.hinges[i].axis;
    kp_[i] = spec.hinges[i].kp;
    kd_[i] = spec.hinges[i].kd;
  }
}

void JointDrive::set_targets(const double* hinge_angles) {
  Eigen::Quaterniond q = rest_;
  for (int i = 0; i < 3; ++i) q = q * Eigen::AngleAxisd(hinge_angles[i], hinge_axes_[i]);
  target_ = q.normalized();
}

void JointDrive::prepare_step(double h) {
  Eigen::Quaterniond qp = from_ode_quat(dBodyGetQuaternion(parent_));
  Eigen::Quaterniond qc = from_ode_quat(dBodyGetQuaternion(child_));
  Eigen::Quaterniond relative = qp.conjugate() * qc;
  error_ = rotation_vector(relative * target_.conjugate());
  static constexpr int kLoStop[3] = {dParamLoStop, dParamLoStop2, dParamLoStop3};
  static constexpr int kHiStop[3] = {dParamHiStop, dParamHiStop2, dParamHiStop3};
  static constexpr int kErp[3] = {dParamStopERP, dParamStopERP2, dParamStopERP3};
  static constexpr int kCfm[3] = {dParamStopCFM, dParamStopCFM2, dParamStopCFM3};
  for (int i = 0; i < 3; ++i) dJointSetAMotorAngle(motor_, i, error_[i]);
  if (h == gains_for_h_) return;
  gains_for_h_ = h;
  for (int i = 0; i < 3; ++i) {
    double denom = h * kp_[i] + kd_[i];
    if (denom <= 0) continue;  // no gains: a free joint
    // Equal stops make ODE treat the row as two-sided, i.e. a spring-damper.
    dJointSetAMotorParam(motor_, kLoStop[i], 0);
    dJointSetAMotorParam(motor_, kHiStop[i], 0);
    dJointSetAMotorParam(motor_, kErp[i], h * kp_[i] / denom);
    dJointSetAMotorParam(motor_, kCfm[i], 1.0 / denom);
  }
}

}  // namespace olympics::core
