// No tunnelling: 10,000 balls fired from random directions at a swinging racket (tennis, up to
// 70 m/s) and at a swinging paddle (table tennis, up to 30 m/s); every contact that dense
// sub-stepping finds, the swept test finds too, no later. And the bounce obeys restitution and
// friction.
#include "equipment/swept_ball.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

namespace olympics::sports::equipment {
namespace {

constexpr double kDt = 1.0 / 120.0;
constexpr int kDenseSamples = 4000;

Pose at(const Pose& a, const Pose& b, double t) {
  return {a.position + t * (b.position - a.position), a.orientation.slerp(t, b.orientation)};
}

Eigen::Vector3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0, 1);
  Eigen::Vector3d v(n(rng), n(rng), n(rng));
  return v.normalized();
}

struct Equipment {
  const char* name;
  Disc disc;
  double ball_radius, max_ball_speed;
};

void PrintTo(const Equipment& e, std::ostream* os) { *os << e.name; }

class NoTunnelling : public ::testing::TestWithParam<Equipment> {};

TEST_P(NoTunnelling, EveryDenseContactIsFoundAndNoLater) {
  const Equipment& e = GetParam();
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(0, 1);
  int hits = 0, swept_only = 0, trials = 0;
  for (int trial = 0; trials < 10000; ++trial) {  // 10,000 balls fired (not starting inside)
    // A swing: up to 20 m/s and 30 rad/s, from a random orientation.
    Pose p0{Eigen::Vector3d::Zero(),
            Eigen::Quaterniond(Eigen::AngleAxisd(M_PI * u(rng), random_unit(rng)))};
    Pose p1{20 * u(rng) * kDt * random_unit(rng),
            p0.orientation *
                Eigen::Quaterniond(Eigen::AngleAxisd(30 * u(rng) * kDt, random_unit(rng)))};
    // The ball passes near the disc at mid-step, from any direction.
    const Eigen::Vector3d aim = at(p0, p1, 0.5).position + 0.3 * u(rng) * random_unit(rng);
    const Eigen::Vector3d v = e.max_ball_speed * u(rng) * random_unit(rng);
    const Eigen::Vector3d b0 = aim - 0.5 * kDt * v, b1 = aim + 0.5 * kDt * v;
    if (ball_disc_distance(b0, e.ball_radius, e.disc, p0) <= 0)
      continue;  // starts inside: ill-posed
    ++trials;
    double first_dense = -1, closest = 1e9;
    for (int k = 0; k <= kDenseSamples; ++k) {
      const double t = static_cast<double>(k) / kDenseSamples;
      const double d = ball_disc_distance(b0 + t * (b1 - b0), e.ball_radius, e.disc, at(p0, p1, t));
      closest = std::min(closest, d);
      if (d <= 0 && first_dense < 0) first_dense = t;
    }
    auto hit = sweep_ball_disc(b0, b1, e.ball_radius, e.disc, p0, p1, kDt);
    if (first_dense >= 0) {
      ++hits;
      ASSERT_TRUE(hit.has_value())
          << e.name << " trial " << trial
          << ": tunnelled through (dense contact at t=" << first_dense << ")";
      EXPECT_LE(hit->t, first_dense + 1e-12) << e.name << " trial " << trial;
      EXPECT_LE(ball_disc_distance(hit->ball_centre, e.ball_radius, e.disc, at(p0, p1, hit->t)),
                1e-4);
    } else if (hit) {
      ++swept_only;  // a graze between two dense samples
      EXPECT_LE(closest, 0.01) << e.name << " trial " << trial
                               << ": a contact nowhere near the disc";
    }
  }
  std::printf("%s: %d trials, %d true contacts, all found; %d grazes found between dense samples\n",
              e.name, trials, hits, swept_only);
  EXPECT_GT(hits, 1000);  // the test exercises contacts, not just misses
}

INSTANTIATE_TEST_SUITE_P(Equipment, NoTunnelling,
                         ::testing::Values(Equipment{"racket", {0.15, 0.02}, 0.032, 70.0},
                                           Equipment{"paddle", {0.08, 0.01}, 0.020, 30.0}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(Bounce, RestitutionOnTheNormalFrictionOnTheTangent) {
  const Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
  // Straight down onto a still surface: the normal speed comes back times e.
  auto v = bounce({0, 0, -10}, Eigen::Vector3d::Zero(), n, 0.8, 0.5);
  EXPECT_NEAR(v.z(), 8.0, 1e-12);
  EXPECT_NEAR(v.x(), 0.0, 1e-12);
  // Oblique: the tangential speed drops by at most mu * (1 + e) * |vn| = 0.5 * 1.8 * 10 = 9.
  v = bounce({20, 0, -10}, Eigen::Vector3d::Zero(), n, 0.8, 0.5);
  EXPECT_NEAR(v.z(), 8.0, 1e-12);
  EXPECT_NEAR(v.x(), 11.0, 1e-12);
  // Friction never reverses the slip: it stops at sticking.
  v = bounce({3, 0, -10}, Eigen::Vector3d::Zero(), n, 0.8, 0.5);
  EXPECT_NEAR(v.x(), 0.0, 1e-12);
  // A moving racket: relative velocities count. Racket at +15 m/s along n hits a still ball.
  v = bounce(Eigen::Vector3d::Zero(), {0, 0, 15}, n, 0.8, 0.5);
  EXPECT_NEAR(v.z(), 15 + 0.8 * 15, 1e-12);
  // Separating already: untouched.
  v = bounce({0, 0, 5}, Eigen::Vector3d::Zero(), n, 0.8, 0.5);
  EXPECT_NEAR(v.z(), 5.0, 1e-12);
}

TEST(SweptBall, FindsTheContactTimeOfAHeadOnShot) {
  // A still disc facing +z at the origin; a ball moving down at 60 m/s covers 0.5 m per step and
  // touches the face when its centre is at z = 0.02 + 0.032. From 1 m up it does not get there.
  Disc disc{0.15, 0.02};
  Pose still;
  EXPECT_FALSE(sweep_ball_disc({0, 0, 1.0}, {0, 0, 0.5}, 0.032, disc, still, still, kDt));
  // From 0.3 m: contact when the centre is at 0.052, t = (0.3 - 0.052) / 0.5 = 0.496.
  auto hit = sweep_ball_disc({0, 0, 0.3}, {0, 0, -0.2}, 0.032, disc, still, still, kDt);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 0.496, 1e-3);
  EXPECT_NEAR(hit->normal.z(), 1.0, 1e-9);
}

}  // namespace
}  // namespace olympics::sports::equipment
