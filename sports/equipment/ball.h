// Balls with real masses, calibrated restitution and quadratic air drag (SPORTS.md, "Balls").
//
// A ball is an ODE sphere in a PhysicsWorld. Restitution is the ball's side of the contact (the
// world takes the larger of the two surfaces'), calibrated so that the official bounce tests come
// out in range with drag acting (tests/core/ball_test.cpp). Drag F = -1/2 rho Cd A |v| v is added
// before every physics step.
#pragma once

#include <ode/ode.h>

#include <Eigen/Core>
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
  // Adds this step's air drag; call before every physics step.
  void prepare_step();
  Eigen::Vector3d position() const;
  Eigen::Vector3d velocity() const;
  void set_state(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity);
  const BallSpec& spec() const { return spec_; }
  dBodyID body() const { return body_; }

  static constexpr double kAirDensity = 1.2;  // kg/m^3

 private:
  BallSpec spec_;
  dBodyID body_;
  std::unique_ptr<core::GeomTag> tag_;
};

}  // namespace olympics::sports::equipment
