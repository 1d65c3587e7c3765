// A humanoid built in a PhysicsWorld from a ModelSpec: ODE bodies, geoms, PD-driven joints.
//
// Bodies keep the MJCF body frame's orientation; ODE needs each body's origin at its centre of
// mass, so positions reported here are converted back to the MJCF body origins (the link frames
// that observations use).
#pragma once

#include <ode/ode.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/joint_drive.h"
#include "core/model_spec.h"
#include "core/physics_world.h"

namespace olympics::core {

struct BodyState {
  Eigen::Vector3d position;  // body origin, world frame
  Eigen::Quaterniond orientation;
  Eigen::Vector3d linear_velocity;  // of the body origin
  Eigen::Vector3d angular_velocity;
};

struct RootPlacement {
  Eigen::Vector3d position{0, 0, 0};  // pelvis origin; z <= 0 means "standing on the ground"
  double yaw = 0;                     // heading about world z, radians
};

class Humanoid {
 public:
  Humanoid(PhysicsWorld& world, const ModelSpec& spec, const RootPlacement& placement = {});
  ~Humanoid();
  Humanoid(const Humanoid&) = delete;
  Humanoid& operator=(const Humanoid&) = delete;

  const ModelSpec& spec() const { return spec_; }
  // The entity id its geoms carry in their GeomTag (PhysicsWorld::add_entity).
  int entity() const { return entity_; }
  int body_count() const { return static_cast<int>(spec_.bodies.size()); }
  int dof_count() const { return dof_count_; }
  double total_mass() const { return total_mass_; }
  // Pelvis height that puts the lowest point of the rest pose on the ground.
  double standing_root_height() const { return standing_root_height_; }
  // Height of the rest pose, lowest sole to top of the head.
  double rest_height() const { return rest_height_; }

  // Puts every body back in the rest pose at the placement, at rest, with zero PD targets.
  void reset(const RootPlacement& placement);
  // Per-hinge PD targets in radians, in action order (dof_count() of them).
  void set_joint_targets(std::span<const double> angles);
  // Call before every physics step.
  void prepare_step(double h);

  BodyState body_state(int body) const;
  std::vector<BodyState> body_states() const;
  dBodyID ode_body(int body) const { return bodies_[body]; }

  // Per body: did it touch the ground since clear_ground_contacts()?
  bool touched_ground(int body) const { return ground_touch_[body] != 0; }
  void clear_ground_contacts();

 private:
  void place_bodies(const RootPlacement& placement);
  bool may_self_collide(int a, int b) const;

  PhysicsWorld& world_;
  ModelSpec spec_;
  int entity_ = -1;
  int dof_count_ = 0;
  double total_mass_ = 0;
  double standing_root_height_ = 0;
  double rest_height_ = 0;
  std::vector<dBodyID> bodies_;
  std::vector<Eigen::Vector3d> com_offset_;  // centre of mass in the body frame
  std::vector<std::unique_ptr<GeomTag>> tags_;
  std::vector<std::uint8_t> ground_touch_;
  std::vector<std::uint8_t> self_collision_allowed_;  // body_count^2
  std::vector<std::unique_ptr<JointDrive>> drives_;   // per body; null for root and welded
  std::vector<dJointID> welds_;
};

}  // namespace olympics::core
