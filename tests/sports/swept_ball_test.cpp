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

// A racket swung about the hand (issue 29, face round: the ball left the face with more sideways
// speed than the planner's bounce gave for the face it saw). The contact itself is traced here: a
// ball met on the face, off its centre, bounces about the face's normal, with the velocity of the
// point it meets, a rigid body's (centre's + spin x lever), the same bounce the planner models.
TEST(SweptBall, AFaceHitOnASwungRacketBouncesAboutTheFaceNormalAtThePointsVelocity) {
  const Disc disc{0.15, 0.02};
  const Eigen::Vector3d pivot(0, 0, 1);  // the hand, turning about the vertical at 20 rad/s
  const double spin = 20;
  // The face's normal (local z) along +x, its centre 0.35 m from the hand along -y: it moves
  // along +x at 0.35 * 20 = 7 m/s.
  auto racket_at = [&](double time) {
    const Eigen::AngleAxisd turn(spin * time, Eigen::Vector3d::UnitZ());
    const Eigen::Quaterniond facing(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()));
    return Pose{pivot + turn * Eigen::Vector3d(0, -0.35, 0), Eigen::Quaterniond(turn) * facing};
  };
  for (const double lever : {0.27, 0.35, 0.43}) {  // met 8 cm inside the centre, on it, outside
    SCOPED_TRACE(lever);
    // The ball comes at 20 m/s along -x, straight at the face, at the lever along -y from the
    // hand and 4 cm above the centre; it meets the face 0.8 of the way through the step.
    const Eigen::Vector3d ball_v(-20, 0, 0);
    const Eigen::Vector3d aim(0.052 + 0.3 * kDt * (20 + spin * lever), -lever, 1.04);
    const Eigen::Vector3d p0 = aim - 0.5 * kDt * ball_v, p1 = aim + 0.5 * kDt * ball_v;
    const Pose pose0 = racket_at(-0.5 * kDt), pose1 = racket_at(0.5 * kDt);
    const auto hit = sweep_ball_disc(p0, p1, 0.032, disc, pose0, pose1, kDt);
    ASSERT_TRUE(hit);
    const Pose face = at(pose0, pose1, hit->t);
    const Eigen::Vector3d face_normal = face.orientation * Eigen::Vector3d::UnitZ();
    // A face hit: the face's normal, not a rim's.
    EXPECT_GT(hit->normal.dot(face_normal), std::cos(0.1 * M_PI / 180));
    // The point met moves as the rigid racket does there, spin x its lever from the hand: along
    // the normal within 1% (the sign and the lever right); sideways within the centre's speed x
    // the turn over half a step (0.08 rad: the sweep moves the centre along the step's chord).
    const Eigen::Vector3d met = hit->ball_centre - 0.032 * hit->normal;
    const Eigen::Vector3d rigid = Eigen::Vector3d(0, 0, spin).cross(met - pivot);
    EXPECT_NEAR(hit->surface_point_velocity.dot(face_normal), rigid.dot(face_normal),
                0.01 * rigid.norm());
    EXPECT_NEAR(rigid.dot(face_normal), spin * lever, 0.02 * spin * lever);
    EXPECT_LT((hit->surface_point_velocity - rigid).norm(), 0.5 * spin * kDt * 0.35 * spin);
  }
}

}  // namespace
}  // namespace olympics::sports::equipment
