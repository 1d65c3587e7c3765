// Inverse kinematics of one limb: the joint rotations that put a point of its last body at a
// position and (optionally) one of its axes along a direction, within joint limits.
//
// Damped least squares on the limb's own joints (each a 3-DoF ball, as in the model), from the
// pose the observation shows: the body above the limb stays where it is. A weak pull toward a
// preferred posture picks one of the many arm poses that reach a point, and keeps the solution
// from wandering between ticks.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "control/body_model.h"

namespace olympics::client::control {

struct LimbJoint {
  int body = 0;                             // the joint between this body and its parent
  Eigen::Vector3d lo{-M_PI, -M_PI, -M_PI};  // Euler x-y-z limits, radians
  Eigen::Vector3d hi{M_PI, M_PI, M_PI};
  Eigen::Vector3d preferred = Eigen::Vector3d::Zero();  // Euler x-y-z
  double stiffness = 1;  // how strongly it keeps its preferred posture (a trunk more than an arm)
};

struct LimbGoal {
  Eigen::Vector3d position;       // where the end point should be (heading frame)
  Eigen::Vector3d axis{0, 0, 0};  // where the end axis should point; zero: anywhere
  bool axis_either_sign = true;   // a two-sided face: -axis does as well
  double axis_weight_m = 0.3;     // metres of position error worth one radian of axis error
  double posture_weight = 0.05;   // pull toward the preferred posture
};

struct LimbSolution {
  std::vector<Eigen::Matrix3d> relative;  // per limb joint, relative to its parent
  Eigen::Vector3d position;               // where the end point got to
  Eigen::Vector3d axis;
  double position_error_m = 0;
  double axis_error_rad = 0;
};

class LimbIk {
 public:
  // `end_point` and `end_axis` are in the last joint's body frame.
  LimbIk(const BodyModel& model, std::vector<LimbJoint> joints, const Eigen::Vector3d& end_point,
         const Eigen::Vector3d& end_axis);

  // Starts from `start` (per limb joint; empty: the pose's own rotations) and iterates.
  LimbSolution solve(const BodyPose& pose, const LimbGoal& goal,
                     const std::vector<Eigen::Matrix3d>& start = {}, int iterations = 40) const;

  // Where the end point and axis are with these joint rotations, the limb's base as in `pose`.
  void end_of(const BodyPose& pose, const std::vector<Eigen::Matrix3d>& relative,
              Eigen::Vector3d& point, Eigen::Vector3d& axis) const;

  const std::vector<LimbJoint>& joints() const { return joints_; }
  // The longest distance from the first joint to the end point (all straight).
  double reach() const { return reach_; }

 private:
  static constexpr int kRestarts = 6;
  LimbSolution descend(const BodyPose& pose, const LimbGoal& goal,
                       const std::vector<Eigen::Matrix3d>& start, int iterations) const;
  // Forward kinematics along the limb from its base as in `pose`; also each joint's position and
  // its parent's rotation when asked.
  void walk(const BodyPose& pose, const std::vector<Eigen::Matrix3d>& relative,
            Eigen::Vector3d& point, Eigen::Vector3d& axis,
            std::vector<Eigen::Vector3d>* joint_pos = nullptr,
            std::vector<Eigen::Matrix3d>* parent_rot = nullptr) const;

  const BodyModel& model_;
  std::vector<LimbJoint> joints_;
  Eigen::Vector3d end_point_, end_axis_;
  double reach_ = 0;
};

}  // namespace olympics::client::control
