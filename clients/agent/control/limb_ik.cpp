#include "control/limb_ik.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <stdexcept>

#include "control/drive_target.h"

namespace olympics::client::control {
namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

Eigen::Matrix3d clamp_to_limits(const Eigen::Matrix3d& r, const LimbJoint& j) {
  const Eigen::Vector3d a = euler_xyz(r);
  return from_euler_xyz(a.cwiseMax(j.lo).cwiseMin(j.hi));
}

}  // namespace

LimbIk::LimbIk(const BodyModel& model, std::vector<LimbJoint> joints,
               const Eigen::Vector3d& end_point, const Eigen::Vector3d& end_axis)
    : model_(model), joints_(std::move(joints)), end_point_(end_point), end_axis_(end_axis) {
  if (joints_.empty()) throw std::invalid_argument("a limb needs at least one joint");
  for (size_t k = 1; k < joints_.size(); ++k)
    if (model_.body(joints_[k].body).parent != joints_[k - 1].body)
      throw std::invalid_argument(
          "limb joints must follow the tree: " + model_.body(joints_[k].body).name +
          " is not a child of " + model_.body(joints_[k - 1].body).name);
  for (size_t k = 1; k < joints_.size(); ++k) reach_ += model_.body(joints_[k].body).offset.norm();
  reach_ += end_point_.norm();
}

void LimbIk::end_of(const BodyPose& pose, const std::vector<Eigen::Matrix3d>& relative,
                    Eigen::Vector3d& point, Eigen::Vector3d& axis) const {
  walk(pose, relative, point, axis);
}

void LimbIk::walk(const BodyPose& pose, const std::vector<Eigen::Matrix3d>& relative,
                  Eigen::Vector3d& point, Eigen::Vector3d& axis,
                  std::vector<Eigen::Vector3d>* joint_pos,
                  std::vector<Eigen::Matrix3d>* parent_rot) const {
  const int base = model_.body(joints_[0].body).parent;
  Eigen::Vector3d p = pose.position[base];
  Eigen::Matrix3d r = pose.rotation[base];
  for (size_t k = 0; k < joints_.size(); ++k) {
    p += r * model_.body(joints_[k].body).offset;
    if (joint_pos) (*joint_pos)[k] = p;
    if (parent_rot) (*parent_rot)[k] = r;
    r = r * relative[k];
  }
  point = p + r * end_point_;
  axis = r * end_axis_;
}

LimbSolution LimbIk::solve(const BodyPose& pose, const LimbGoal& goal,
                           const std::vector<Eigen::Matrix3d>& start, int iterations) const {
  // Joint limits make local minima (an arm straight at its elbow's stop): when the first start
  // does not reach, others do, from postures spread over the joints' ranges (a fixed set, so
  // the result is deterministic).
  LimbSolution best = descend(pose, goal, start, iterations);
  const double tolerance = 0.005;
  auto score = [&](const LimbSolution& s) {
    return s.position_error_m + goal.axis_weight_m * s.axis_error_rad;
  };
  for (int k = 0; k < kRestarts && score(best) > tolerance; ++k) {
    std::vector<Eigen::Matrix3d> seed;
    for (size_t j = 0; j < joints_.size(); ++j) {
      const LimbJoint& joint = joints_[j];
      Eigen::Vector3d a;
      for (int axis = 0; axis < 3; ++axis) {
        // A low-discrepancy spread: fraction (k + 1) * golden ratio + per-joint shift.
        const double u = std::fmod((k + 1) * 0.6180339887 + 0.37 * (3 * j + axis), 1.0);
        a[axis] = joint.lo[axis] + (0.2 + 0.6 * u) * (joint.hi[axis] - joint.lo[axis]);
      }
      seed.push_back(k == 0 ? from_euler_xyz(joint.preferred) : from_euler_xyz(a));
    }
    LimbSolution s = descend(pose, goal, seed, iterations);
    if (score(s) < score(best)) best = std::move(s);
  }
  return best;
}

LimbSolution LimbIk::descend(const BodyPose& pose, const LimbGoal& goal,
                             const std::vector<Eigen::Matrix3d>& start, int iterations) const {
  const int n = static_cast<int>(joints_.size());
  std::vector<Eigen::Matrix3d> rel(n);
  for (int k = 0; k < n; ++k) {
    const int b = joints_[k].body;
    rel[k] =
        start.empty()
            ? Eigen::Matrix3d(pose.rotation[model_.body(b).parent].transpose() * pose.rotation[b])
            : start[k];
  }
  const bool use_axis = goal.axis.norm() > 1e-9;
  Eigen::Vector3d want_axis = use_axis ? goal.axis.normalized() : Eigen::Vector3d::Zero();
  if (use_axis && goal.axis_either_sign) {
    Eigen::Vector3d p, a;
    end_of(pose, rel, p, a);
    if (a.dot(want_axis) < 0) want_axis = -want_axis;
  }
  const int rows = 3 + (use_axis ? 3 : 0) + 3 * n;
  std::vector<Eigen::Vector3d> joint_pos(n);
  std::vector<Eigen::Matrix3d> parent_rot(n);
  for (int it = 0; it < iterations; ++it) {
    // Forward along the limb, keeping each joint's position and its parent's rotation.
    Eigen::Vector3d end, axis;
    walk(pose, rel, end, axis, &joint_pos, &parent_rot);

    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(rows, 3 * n);
    Eigen::VectorXd e = Eigen::VectorXd::Zero(rows);
    e.head<3>() = goal.position - end;
    const double w_axis = goal.axis_weight_m;
    if (use_axis) e.segment<3>(3) = w_axis * (want_axis - axis);
    const int posture_row = use_axis ? 6 : 3;
    // The posture pull picks a pose early on, then lets go so the goal is met to the millimetre.
    const double w_posture = goal.posture_weight * (3 * it < 2 * iterations ? 1.0 : 0.05);
    for (int k = 0; k < n; ++k) {
      J.block<3, 3>(0, 3 * k) = -skew(end - joint_pos[k]) * parent_rot[k];
      if (use_axis) J.block<3, 3>(3, 3 * k) = -w_axis * skew(axis) * parent_rot[k];
      const double w = w_posture * joints_[k].stiffness;
      J.block<3, 3>(posture_row + 3 * k, 3 * k) = w * Eigen::Matrix3d::Identity();
      e.segment<3>(posture_row + 3 * k) =
          -w * log_rotation(rel[k] * from_euler_xyz(joints_[k].preferred).transpose());
    }
    const double damping = 1e-3;
    Eigen::MatrixXd A = J.transpose() * J;
    A.diagonal().array() += damping;
    Eigen::VectorXd step = A.ldlt().solve(J.transpose() * e);
    const double largest = step.cwiseAbs().maxCoeff();
    if (largest > 0.4) step *= 0.4 / largest;
    for (int k = 0; k < n; ++k)
      rel[k] = clamp_to_limits(exp_rotation(step.segment<3>(3 * k)) * rel[k], joints_[k]);
  }
  LimbSolution s;
  s.relative = rel;
  end_of(pose, rel, s.position, s.axis);
  s.position_error_m = (s.position - goal.position).norm();
  s.axis_error_rad = use_axis ? std::acos(std::clamp(s.axis.dot(want_axis), -1.0, 1.0)) : 0.0;
  return s;
}

}  // namespace olympics::client::control
