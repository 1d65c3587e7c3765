#include "golf/golf_green.h"

#include <cmath>

namespace olympics::sports::golf {
namespace {

constexpr int kWalls = 24;
constexpr double kWallThickness = 0.01;
constexpr double kHeldSpeed = 0.01;  // m/s: slower, a ball on a gentle slope is held at rest

}  // namespace

double rolling_resistance_for_stimp(double stimp) {
  // The ball slows by (25/21) c_rr g rolling (ball.cpp's force with I = 2/5 m r^2);
  // v^2 = 2 a d.
  const double decel = kStimpSpeed * kStimpSpeed / (2 * stimp);
  return decel * 21.0 / 25.0 / 9.81;
}

Eigen::Vector3d slope_force(const equipment::Ball& ball, const GreenSlope& slope) {
  if (slope.grade <= 0 || !ball.on_ground()) return Eigen::Vector3d::Zero();
  constexpr double g = 9.81;
  const double pull = ball.spec().mass * g * slope_sine(slope.grade);
  const Eigen::Vector3d v = ball.velocity();
  const bool at_rest = Eigen::Vector2d(v.x(), v.y()).norm() < kHeldSpeed;
  const double holding = (5.0 / 3.0) * ball.spec().mass * ball.spec().rolling_resistance * g;
  if (at_rest && pull <= holding) return Eigen::Vector3d::Zero();
  return pull * slope.downhill;
}

Hole::Hole(core::PhysicsWorld& world, const HoleSpec& spec) : spec_(spec) {
  const double r = spec.radius, t = kWallThickness, d = spec.depth;
  const double half_chord = (r + t) * std::tan(M_PI / kWalls);
  for (int i = 0; i < kWalls; ++i) {
    const double a = 2 * M_PI * i / kWalls;
    const Eigen::Vector3d centre{spec.centre.x() + (r + 0.5 * t) * std::cos(a),
                                 spec.centre.y() + (r + 0.5 * t) * std::sin(a), -0.5 * d};
    dGeomID wall = world.add_static_box(centre, {0.5 * t, half_chord, 0.5 * d}, 0.5, 0.0);
    const dReal yaw = a;
    dMatrix3 rot;
    dRFromAxisAndAngle(rot, 0, 0, 1, yaw);
    dGeomSetRotation(wall, rot);
  }
  world.add_static_box({spec.centre.x(), spec.centre.y(), -d - 0.01}, {r + t, r + t, 0.01}, 0.5,
                       0.0);
}

bool Hole::over(const Eigen::Vector3d& p) const {
  return (p.head<2>() - spec_.centre).norm() < spec_.radius;
}

bool Hole::holds(const Eigen::Vector3d& c, double ball_radius) const {
  return over(c) && c.z() + ball_radius < 0;
}

void Hole::before_step(equipment::Ball& ball) const {
  ball.set_ground_holds(!over(ball.position()));
}

}  // namespace olympics::sports::golf
