// The agent's own model of its body: the same humanoid asset the server loads (joint tree, masses,
// centres of mass, PD gains), with the sport's equipment attached as the server attaches it, and
// the body's pose rebuilt from the self observation.
//
// Frames: everything is in the heading frame of the self observation (z up, x the root's heading,
// origin at the root), since that is what a client sees; gravity is -z there as in the world.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <span>
#include <string>
#include <vector>

#include "core/humanoid_assets.h"
#include "core/model_spec.h"

namespace olympics::sports::equipment {
struct EquipmentSpec;
}

namespace olympics::client::control {

struct ModelBody {
  std::string name;
  int parent = -1;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  // origin in the parent's frame
  double mass = 0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();  // centre of mass in the body's frame
  Eigen::Vector3d kp = Eigen::Vector3d::Zero();   // per hinge (x, y, z), N m / rad
  Eigen::Vector3d kd = Eigen::Vector3d::Zero();
};

// Where each body is, as the self observation tells it (heading frame).
struct BodyPose {
  std::vector<Eigen::Vector3d> position;  // body origins; the root at 0
  std::vector<Eigen::Matrix3d> rotation;  // body frame to heading frame
};

class BodyModel {
 public:
  explicit BodyModel(const core::ModelSpec& spec);
  // The project's SMPL or SMPL-X humanoid, holding `equipment` when it is given.
  static BodyModel humanoid(core::HumanoidKind kind,
                            const sports::equipment::EquipmentSpec* equipment = nullptr);

  int size() const { return static_cast<int>(bodies_.size()); }
  const ModelBody& body(int i) const { return bodies_[i]; }
  double total_mass() const { return total_mass_; }  // kg, every body
  // Is `body` `ancestor` or below it in the tree?
  bool in_subtree(int body, int ancestor) const;

  // The pose of every body from an SMPL or SMPL-X self observation (its first 358 or 778 floats).
  BodyPose pose_from_observation(std::span<const float> observation) const;
  // Forward kinematics: body rotations relative to their parents (rotation[0]: the root's, in
  // the heading frame) to a pose with the root at the origin.
  BodyPose forward(const std::vector<Eigen::Matrix3d>& relative) const;
  // Rotations relative to the parents (the root's: its own) from a pose.
  std::vector<Eigen::Matrix3d> relative_rotations(const BodyPose& pose) const;

  // Centre of mass of the whole body, heading frame.
  Eigen::Vector3d centre_of_mass(const BodyPose& pose) const;
  // The torque gravity exerts on the subtree below joint `body` about that joint, in the parent
  // body's frame (what the joint's drive must hold).
  Eigen::Vector3d gravity_torque(const BodyPose& pose, int body) const;
  // The inertial load on joint `body` while everything below it turns as one about the vertical
  // through `pivot` (heading frame) at `rate` rad/s, speeding up at `acceleration` rad/s²: the
  // torque about the joint of the forces that do not come (each body's mass times minus its
  // centripetal and tangential acceleration; the bodies' own rotational inertia left out),
  // parent frame, the way `gravity_torque` is (a drive holds it as it holds a weight).
  Eigen::Vector3d turning_torque(const BodyPose& pose, int body, const Eigen::Vector3d& pivot,
                                 double rate, double acceleration) const;
  // The torque gravity exerts about joint `body` on everything NOT below it (the body it holds
  // up when its limb stands on the ground, e.g. a stance leg's joints), parent frame.
  Eigen::Vector3d gravity_torque_above(const BodyPose& pose, int body) const;

 private:
  // Body b's centre of mass, heading frame.
  Eigen::Vector3d body_com(const BodyPose& pose, int b) const;
  // A torque about joint `body` (heading frame) in its parent body's frame (the root's: as is).
  Eigen::Vector3d in_parent_frame(const BodyPose& pose, int body,
                                  const Eigen::Vector3d& torque) const;
  // Body b's weight's torque about a point, heading frame.
  Eigen::Vector3d weight_torque(const BodyPose& pose, int b, const Eigen::Vector3d& about) const;

  std::vector<ModelBody> bodies_;
  std::vector<std::vector<int>> subtree_;  // per body: itself and every descendant
  double total_mass_ = 0;
};

}  // namespace olympics::client::control
