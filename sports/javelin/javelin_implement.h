// A javelin in a PhysicsWorld: one rigid body whose origin is its centre of mass, its axis the
// body's x (the tip ahead), with two geoms, the metal head (geom 0, a thin capsule ending at
// the tip) and the shaft (geom 1). Held by a grip joint: an ODE fixed joint between the hand's
// palm and the javelin at the cord, made while the fingers hold it and broken when they open
// (javelin_match.cpp); while held, the holder's hand does not collide with it (ODE's category
// bits), so the joint alone carries it.
#pragma once

#include <ode/ode.h>

#include <Eigen/Geometry>
#include <memory>

#include "core/physics_world.h"
#include "javelin/javelin_rules.h"

namespace olympics::sports::javelin {

class Javelin {
 public:
  static constexpr int kHeadGeom = 0, kShaftGeom = 1;

  Javelin(core::PhysicsWorld& world, const JavelinSpec& spec);
  ~Javelin();
  Javelin(const Javelin&) = delete;
  Javelin& operator=(const Javelin&) = delete;

  const JavelinSpec& spec() const { return spec_; }
  dBodyID body() const { return body_; }
  int entity() const { return head_tag_->entity; }
  const core::GeomTag* head_tag() const { return head_tag_.get(); }
  const core::GeomTag* shaft_tag() const { return shaft_tag_.get(); }

  Eigen::Vector3d centre() const;  // the centre of mass
  Eigen::Quaterniond orientation() const;
  Eigen::Vector3d axis() const { return orientation() * Eigen::Vector3d::UnitX(); }
  Eigen::Vector3d tip() const { return centre() + spec_.tip_to_com * axis(); }
  Eigen::Vector3d grip_point() const {
    return centre() + (spec_.tip_to_com - spec_.tip_to_grip) * axis();
  }
  Eigen::Vector3d velocity() const;
  Eigen::Vector3d spin() const;

  // Puts the javelin at rest with its cord's middle at `grip` and its body frame at `q`.
  void place(const Eigen::Vector3d& grip, const Eigen::Quaterniond& q);
  // Sets its motion (tests, the flight bench).
  void set_motion(const Eigen::Vector3d& velocity, const Eigen::Vector3d& spin);
  // The air's load (javelin_aero.h), added before a physics step.
  void add_aerodynamic_load();

  // The grip: a fixed joint to `palm` where the javelin now is; the `hand` geoms (palm and
  // fingers) stop colliding with it until release().
  void grip(dBodyID palm, const std::vector<dGeomID>& hand);
  void release();
  bool held() const { return grip_ != nullptr; }

 private:
  void set_hand_collisions(bool held);

  JavelinSpec spec_;
  dWorldID world_;
  dBodyID body_;
  std::unique_ptr<core::GeomTag> head_tag_, shaft_tag_;
  dGeomID head_ = nullptr, shaft_ = nullptr;
  dJointID grip_ = nullptr;
  std::vector<dGeomID> hand_;
};

}  // namespace olympics::sports::javelin
