// The putting surface and the hole (the Rules of Golf, Definitions: "hole" 108 mm across, at
// least 101.6 mm deep). The ground plane is the green and the fairway; they differ only in their
// rolling resistance (equipment::Ball's c_rr: a force against a ball rolling on the ground), each
// calibrated on a stimpmeter-like roll: a ball rolling at 1.83 m/s (the speed it leaves the
// stimpmeter's ramp) stops after `stimp` metres (tests/sports/golf/golf_green_test.cpp).
//
// The hole is a cup below the plane: 24 upright wall boxes round a 54 mm circle, their top edges
// the lip, and a floor 101.6 mm down. While the ball's centre is over the circle the plane does
// not hold it (GeomTag::passes_ground): it falls, and the solver's contacts with the lip decide
// whether it drops in (slow) or rides over the far lip and out (fast).
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "core/physics_world.h"
#include "equipment/ball.h"

namespace olympics::sports::golf {

inline constexpr double kStimpSpeed = 1.83;  // m/s off the stimpmeter's ramp

// The c_rr that makes a ball of `ball` roll `stimp` metres from kStimpSpeed on a plane (a
// solid ball: the force at its centre slows it by 21/25 of its nominal decel; see ball.cpp).
double rolling_resistance_for_stimp(double stimp);

// A green that is not flat: a plane falling `grade` (rise over run: 0.02 is a 2% slope) along
// `downhill` (unit, horizontal). The physics' ground stays level; the slope acts on a ball on
// the ground as the along-slope part of gravity, m g sin(theta) at its centre, which the
// ground's friction turns into rolling: (5/7) g sin(theta) for a solid ball, against the
// rolling resistance's (25/21) c_rr g. (The normal force's cos(theta) is left out: 0.02% at 2%.)
// A ball at rest stays at rest while the slope's force is no more than the rolling resistance's,
// (5/3) m c_rr g: sin(theta) <= 7.8% on a stimp-10 green (greens' hole locations rarely exceed
// 3%). A ball in the air feels none of it.
struct GreenSlope {
  Eigen::Vector3d downhill = Eigen::Vector3d::UnitX();
  double grade = 0;
};

// The slope's force on `ball` this step (zero off the ground, or held at rest).
Eigen::Vector3d slope_force(const equipment::Ball& ball, const GreenSlope& slope);

// sin(theta) of a grade.
inline double slope_sine(double grade) { return grade / std::sqrt(1 + grade * grade); }

struct HoleSpec {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0.054;  // 108 mm across
  double depth = 0.1016;  // at least 4 in
};

class Hole {
 public:
  // Builds the cup's walls and floor as static geoms of `world`.
  Hole(core::PhysicsWorld& world, const HoleSpec& spec);
  const HoleSpec& spec() const { return spec_; }
  // Is the point (a ball's centre) over the hole's circle?
  bool over(const Eigen::Vector3d& p) const;
  // Holed (Rules, Definitions): at rest in the hole with all of the ball below the surface.
  bool holds(const Eigen::Vector3d& ball_centre, double ball_radius) const;
  // Lets the ball fall through the plane while its centre is over the hole; call before every
  // physics step.
  void before_step(equipment::Ball& ball) const;

 private:
  HoleSpec spec_;
};

}  // namespace olympics::sports::golf
