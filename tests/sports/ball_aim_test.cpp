// The client's flight prediction (clients/agent/ball_aim.h), which the scripted free-throw
// shooter aims with, against a closed form and against the server's own ball in ODE.
#include "ball_aim.h"

#include <gtest/gtest.h>

#include <cmath>

#include "equipment/ball.h"

namespace olympics::client {
namespace {

TEST(BallAim, WithoutDragTheSpeedIsTheClosedFormOne) {
  // A projectile at elevation a through (x, z): v^2 = g x^2 / (2 cos^2 a (x tan a - z)).
  const double a = 60 * M_PI / 180, x = 3.5, z = 1.6;
  const double closed =
      std::sqrt(9.81 * x * x / (2 * std::pow(std::cos(a), 2) * (x * std::tan(a) - z)));
  // Integrated at 0.1 ms instead of the server's step, the path is the parabola's.
  EXPECT_NEAR(launch_speed_for(x, z, a, 0.0, 1e-4), closed, 2e-3);
  EXPECT_NEAR(carry_to_height(closed, a, z, 0.0, 1e-4), x, 2e-3);
}

TEST(BallAim, OutOfReachAndBelowTheHeightAreSaid) {
  EXPECT_LT(carry_to_height(3.0, M_PI / 4, 2.0, 0.0), 0) << "its apex is 0.23 m up, under 2 m";
  EXPECT_EQ(launch_speed_for(500.0, 1.0, M_PI / 4, 0.02), 0.0) << "no speed up to 40 m/s";
}

TEST(BallAim, TheServersBasketballComesDownWhereTheAimSaid) {
  // A free throw's numbers: 3.55 m across, 1.6 m up, 60 degrees. The ball in ODE (gravity,
  // drag added before each 120 Hz step, as in a match) must come down through the height
  // within 1 cm of the carry the solution was asked for.
  const sports::equipment::BallSpec spec = sports::equipment::basketball();
  const double drag = drag_per_mass(spec.radius, spec.mass, spec.drag_coefficient);
  const double carry = 3.55, rise = 1.6, a = 60 * M_PI / 180;
  const double speed = launch_speed_for(carry, rise, a, drag);
  EXPECT_GT(speed, launch_speed_for(carry, rise, a, 0.0) + 0.1) << "drag asks for more speed";

  core::PhysicsWorld world;
  const Eigen::Vector3d from(0, 0, 1.5);
  sports::equipment::Ball ball(world, spec, from,
                               speed * Eigen::Vector3d(std::cos(a), 0, std::sin(a)));
  const double dt = 1.0 / 120;
  Eigen::Vector3d last = from;
  double crossed_at = -1;
  for (int step = 0; step < 240 && crossed_at < 0; ++step) {
    ball.prepare_step(dt);
    world.step(dt);
    const Eigen::Vector3d p = ball.position();
    if (ball.velocity().z() < 0 && last.z() >= from.z() + rise && p.z() < from.z() + rise)
      crossed_at =
          last.x() + (p.x() - last.x()) * (last.z() - from.z() - rise) / (last.z() - p.z());
    last = p;
  }
  EXPECT_NEAR(crossed_at, carry, 0.01);
}

}  // namespace
}  // namespace olympics::client
