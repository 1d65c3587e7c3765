// The green and the hole: a putt's roll-out against the stimpmeter-like figures (green, fairway),
// and the hole: a ball slow over it drops in, a fast one rides over the far lip and rolls on.
#include "golf/golf_green.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "core/physics_world.h"
#include "golf/golf_match.h"

namespace olympics::sports::golf {
namespace {

using equipment::Ball;

constexpr double kDt = 1.0 / 120.0;

struct Putt {
  double distance = 0;  // m rolled
  bool holed = false;
  Eigen::Vector3d end = Eigen::Vector3d::Zero();
};

// A ball rolling without slipping at `speed` along x from the origin on a green of `stimp` (and
// over a hole at `hole_x`, if any): where it ends after 10 s.
Putt roll(double speed, double stimp, std::optional<double> hole_x = std::nullopt,
          double hole_y = 0) {
  core::PhysicsWorld world;
  const equipment::BallSpec spec = rules_golf_ball();
  Ball ball(world, spec, {0, 0, spec.radius});
  ball.set_rolling_resistance(rolling_resistance_for_stimp(stimp));
  std::optional<Hole> hole;
  if (hole_x) hole.emplace(world, HoleSpec{{*hole_x, hole_y}});
  const Eigen::Vector3d v(speed, 0, 0);
  ball.set_state(ball.position(), v, ball.rolling_spin(v));
  for (int step = 0; step < 120 * 10; ++step) {
    if (hole) hole->before_step(ball);
    ball.prepare_step(kDt);
    world.step(kDt);
  }
  Putt p;
  p.end = ball.position();
  p.distance = p.end.x();
  p.holed = hole && hole->holds(p.end, spec.radius);
  return p;
}

TEST(GolfGreen, AStimpRollStopsAtTheGreensFigure) {
  const Putt green = roll(kStimpSpeed, 3.05), fairway = roll(kStimpSpeed, 1.52);
  std::printf("stimp roll from %.2f m/s: green %.3f m (stimp 10: 3.05), fairway %.3f m (1.52)\n",
              kStimpSpeed, green.distance, fairway.distance);
  EXPECT_NEAR(green.distance, 3.05, 0.15);
  EXPECT_NEAR(fairway.distance, 1.52, 0.08);
  EXPECT_NEAR(green.end.y(), 0.0, 1e-6) << "a straight putt rolls straight";
  EXPECT_NEAR(green.end.z(), rules_golf_ball().radius, 0.002) << "on the green, not in it";
}

TEST(GolfHole, ASlowBallOverTheHoleDrops) {
  // Rolling at 0.5 m/s, it reaches a hole 0.1 m ahead at about 0.5 m/s.
  const Putt p = roll(0.5, 3.05, 0.1);
  std::printf("0.5 m/s at a hole 0.1 m ahead: ends at (%.3f, %.3f, %.3f), holed %d\n", p.end.x(),
              p.end.y(), p.end.z(), p.holed);
  EXPECT_TRUE(p.holed);
  EXPECT_LT(p.end.z(), -0.05) << "it lies on the cup's floor";
}

TEST(GolfHole, AFastBallLipsOutOverTheHole) {
  const Putt p = roll(3.0, 3.05, 0.1);
  std::printf("3.0 m/s at a hole 0.1 m ahead: ends at (%.3f, %.3f, %.3f), holed %d\n", p.end.x(),
              p.end.y(), p.end.z(), p.holed);
  EXPECT_FALSE(p.holed);
  EXPECT_GT(p.distance, 1.0) << "it rolled on past the hole";
  EXPECT_GT(p.end.z(), 0.0) << "on the green beyond";
}

TEST(GolfHole, ABallMissingTheHoleRollsByAndTheCaptureSpeedIsRealistic) {
  // Past the hole's edge (centre 60 mm to the side of a 54 mm hole): no effect.
  const Putt by = roll(1.0, 3.05, 0.5, 0.06 + 0.0);
  EXPECT_FALSE(by.holed);
  EXPECT_NEAR(by.end.y(), 0.0, 1e-3);
  // Holmes (1991): a putt through the hole's centre drops up to about 1.3-1.6 m/s.
  double fastest = 0;
  for (double v = 0.4; v <= 2.4; v += 0.1)
    if (roll(v, 3.05, 0.1).holed) fastest = v;
  std::printf("fastest central putt that drops (0.1 m/s steps): %.1f m/s\n", fastest);
  EXPECT_GE(fastest, 0.9);
  EXPECT_LE(fastest, 2.0);
}

}  // namespace
}  // namespace olympics::sports::golf
