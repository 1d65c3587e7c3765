// Balls with real masses, calibrated restitution and quadratic air drag (SPORTS.md, "Balls").
//
// A ball is an ODE sphere in a PhysicsWorld. Restitution is the ball's side of the contact (the
// world takes the larger of the two surfaces'), calibrated so that the official bounce tests come
// out in range with drag acting (tests/sports/ball_test.cpp). Drag F = -1/2 rho Cd A |v| v is added
// before every physics step, and, for a ball on the ground, rolling resistance (grass): a force
// against the horizontal velocity sized so that a rolling ball slows by c_rr * g.
#pragma once

#include <ode/ode.h>

#include <Eigen/Geometry>
#include <memory>
#include <string>

#include "core/physics_world.h"

namespace olympics::sports::equipment {

struct BallSpec {
  std::string name;
  double radius = 0;       // m
  double mass = 0;         // kg
  double restitution = 0;  // against a rigid floor
  double drag_coefficient = 0;
  double friction = 0.5;
  double rolling_resistance = 0;  // c_rr: a rolling ball slows by c_rr * g on the ground
};

// The balls of the sports, from SPORTS.md (restitution calibrated here, see ball.cpp).
BallSpec tennis_ball();
BallSpec table_tennis_ball();
BallSpec soccer_ball();
BallSpec basketball();
BallSpec golf_ball();

class Ball {
 public:
  Ball(core::PhysicsWorld& world, const BallSpec& spec, const Eigen::Vector3d& position,
       const Eigen::Vector3d& velocity = Eigen::Vector3d::Zero());
  // Adds this step's air drag and rolling resistance; call before every physics step of `dt`.
  void prepare_step(double dt);
  Eigen::Vector3d position() const;
  Eigen::Vector3d velocity() const;
  Eigen::Vector3d angular_velocity() const;
  Eigen::Quaterniond orientation() const;
  void set_state(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                 const Eigen::Vector3d& spin = Eigen::Vector3d::Zero());
  // Moves the ball without changing its velocity, spin or orientation.
  void move_to(const Eigen::Vector3d& position);
  // Does the ball rest or roll on the ground (within a few mm, not flying up or down)?
  bool on_ground() const;
  // The spin of a ball rolling without slipping at `velocity` on the ground.
  Eigen::Vector3d rolling_spin(const Eigen::Vector3d& velocity) const;
  const BallSpec& spec() const { return spec_; }
  dBodyID body() const { return body_; }
  int entity() const { return tag_->entity; }
  // Report the ball's contacts after each step (PhysicsWorld::sensed_contacts): who touched it.
  void sense_contacts() { tag_->sensor = true; }
  // The surface under the ball changed (a golf green, a fairway): its c_rr from now on.
  void set_rolling_resistance(double c_rr) { spec_.rolling_resistance = c_rr; }
  // Whether the ground plane holds the ball (false: it falls through, into a hole).
  void set_ground_holds(bool holds) { tag_->passes_ground = !holds; }

  static constexpr double kAirDensity = 1.2;  // kg/m^3

 private:
  BallSpec spec_;
  dBodyID body_;
  std::unique_ptr<core::GeomTag> tag_;
};

}  // namespace olympics::sports::equipment
