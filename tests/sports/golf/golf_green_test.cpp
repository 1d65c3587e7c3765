// The green and the hole: a putt's roll-out against the stimpmeter-like figures (green, fairway),
// and the hole: a ball slow over it drops in, a fast one rides over the far lip and rolls on.
#include "golf/golf_green.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

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

// A ball rolling without slipping at `v` from the origin on a green of `stimp` falling as
// `slope`: its path, sampled every step, for `seconds`.
std::vector<Eigen::Vector3d> roll_on_slope(const Eigen::Vector3d& v, double stimp,
                                           const GreenSlope& slope, double seconds) {
  core::PhysicsWorld world;
  const equipment::BallSpec spec = rules_golf_ball();
  Ball ball(world, spec, {0, 0, spec.radius});
  ball.set_rolling_resistance(rolling_resistance_for_stimp(stimp));
  ball.set_state(ball.position(), v, ball.rolling_spin(v));
  std::vector<Eigen::Vector3d> path;
  for (int step = 0; step < std::lround(seconds / kDt); ++step) {
    ball.prepare_step(kDt);
    const Eigen::Vector3d pull = slope_force(ball, slope);
    dBodyAddForce(ball.body(), pull.x(), pull.y(), pull.z());
    world.step(kDt);
    path.push_back(ball.position());
  }
  return path;
}

// The slope and rolling resistance as equations of motion of the ball's centre, integrated
// apart from the physics: rolling, a = (5/7) g sin(theta) downhill - (25/21) c_rr g along the
// velocity; at rest, held while the slope's force is within the resistance's.
Eigen::Vector2d model_stop(Eigen::Vector2d v, double stimp, const GreenSlope& slope) {
  const double g = 9.81, c_rr = rolling_resistance_for_stimp(stimp);
  const double s = slope_sine(slope.grade), h = 1e-5;
  const Eigen::Vector2d down = slope.downhill.head<2>();
  Eigen::Vector2d p = Eigen::Vector2d::Zero();
  for (int i = 0; i < 3000000; ++i) {
    const double speed = v.norm();
    if (speed < 1e-4) break;  // stopped: the slopes here are within the hold
    const Eigen::Vector2d a = (5.0 / 7.0) * g * s * down - (25.0 / 21.0) * c_rr * g * v / speed;
    v += h * a;
    p += h * v;
  }
  return p;
}

TEST(GolfGreenSlope, DownhillRollsFartherAndUphillShorterAsGravitySays) {
  // 1.2 m/s on stimp 10 (rolling decel 0.549 m/s^2) with a 3% slope ((5/7) g sin = 0.210):
  // v^2 / 2a: flat 1.311 m, downhill 1.2^2 / (2 x 0.339) = 2.12 m, uphill 1.2^2 / 1.518 = 0.949 m.
  const double g = 9.81, speed = 1.2, grade = 0.03;
  const double resist = (25.0 / 21.0) * rolling_resistance_for_stimp(3.05) * g;
  const double pull = (5.0 / 7.0) * g * slope_sine(grade);
  const Eigen::Vector3d v(speed, 0, 0);
  const double down = roll_on_slope(v, 3.05, {Eigen::Vector3d::UnitX(), grade}, 12).back().x();
  const double up = roll_on_slope(v, 3.05, {-Eigen::Vector3d::UnitX(), grade}, 12).back().x();
  const double flat = roll_on_slope(v, 3.05, {}, 12).back().x();
  std::printf(
      "1.2 m/s on a 3%% slope: downhill %.3f m (model %.3f), uphill %.3f m (%.3f), "
      "flat %.3f m (%.3f)\n",
      down, speed * speed / (2 * (resist - pull)), up, speed * speed / (2 * (resist + pull)), flat,
      speed * speed / (2 * resist));
  EXPECT_NEAR(down, speed * speed / (2 * (resist - pull)), 0.05 * down);
  EXPECT_NEAR(up, speed * speed / (2 * (resist + pull)), 0.05 * up);
  EXPECT_NEAR(flat, speed * speed / (2 * resist), 0.05 * flat);
  const auto back = roll_on_slope(v, 3.05, {-Eigen::Vector3d::UnitX(), grade}, 12);
  EXPECT_NEAR(back[back.size() - 1].x(), back[back.size() - 240].x(), 1e-3)
      << "stopped uphill on a 3% slope, it stays (held by the rolling resistance)";
}

TEST(GolfGreenSlope, ABallAtRestOnASteepSlopeSetsOffAsComputed) {
  // 10% on stimp 10: (5/7) g sin = 0.697 m/s^2 beats 0.549: the ball sets off at 0.148 m/s^2.
  const double g = 9.81, grade = 0.10;
  const double a =
      (5.0 / 7.0) * g * slope_sine(grade) - (25.0 / 21.0) * rolling_resistance_for_stimp(3.05) * g;
  const auto steep = roll_on_slope(Eigen::Vector3d::Zero(), 3.05, {{0, 1, 0}, grade}, 2);
  std::printf("at rest on 10%%: %.4f m in 2 s (model %.4f)\n", steep.back().y(), 0.5 * a * 4);
  EXPECT_NEAR(steep.back().y(), 0.5 * a * 2 * 2, 0.1 * 0.5 * a * 4);
  EXPECT_NEAR(steep.back().x(), 0, 1e-9);
  const auto gentle = roll_on_slope(Eigen::Vector3d::Zero(), 3.05, {{0, 1, 0}, 0.03}, 2);
  EXPECT_EQ(gentle.back().head<2>(), Eigen::Vector2d::Zero()) << "held at rest on 3%";
}

TEST(GolfGreenSlope, APuttAcrossTheSlopeBreaksDownhillAsTheEquationsOfMotionSay) {
  // 1.5 m/s straight along x on a 2% slope falling to the left (+y): the ball curves left.
  const GreenSlope slope{{0, 1, 0}, 0.02};
  const auto path = roll_on_slope({1.5, 0, 0}, 3.05, slope, 12);
  const Eigen::Vector2d end = path.back().head<2>();
  const Eigen::Vector2d model = model_stop({1.5, 0}, 3.05, slope);
  std::printf("1.5 m/s across 2%%: stops at (%.3f, %.3f), the model's (%.3f, %.3f)\n", end.x(),
              end.y(), model.x(), model.y());
  EXPECT_GT(model.y(), 0.2) << "a break worth reading";
  EXPECT_NEAR(end.x(), model.x(), 0.05 * model.x());
  EXPECT_NEAR(end.y(), model.y(), 0.08 * model.y());
  EXPECT_GT(path[path.size() / 4].y(), 0.0);
}

}  // namespace
}  // namespace olympics::sports::golf
