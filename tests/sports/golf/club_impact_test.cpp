// The club-ball impact model (club_impact.h) against hand-computed numbers: a driver face at
// 40 m/s on a resting ball (the reduced mass, (1 + e), the loft, friction up to rolling), a
// glancing face that only rolls the ball, and no impulse when face and ball are parting.
#include "golf/club_impact.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "golf/golf_club.h"
#include "golf/golf_match.h"

namespace olympics::sports::golf {
namespace {

ImpactBall resting_ball() {
  const equipment::BallSpec b = rules_golf_ball();
  return {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), b.mass, b.radius,
          0.4 * b.mass * b.radius * b.radius};
}

TEST(ClubImpact, ADriverAtFortyMetresPerSecondByHand) {
  // Face moving along +x, its normal lofted 10.5 degrees up. By hand (python, 17 digits):
  // reduced mass 0.04593 * 0.2 / 0.24593 = 0.0373520920587; normal impulse
  // 1.83 * 0.0373520920587 * 40 cos 10.5 = 2.68838915675 N s; to roll: 40 sin 10.5 /
  // (1 / 0.0373520920587 + r^2 / I) = 0.0897679694969 N s (< 0.8 x the normal: it rolls);
  // ball: 58.5323134499 m/s along the normal, 1.95445176349 m/s down the face: 58.5649348970
  // m/s, launched 10.5 - atan(1.954 / 58.53) = 8.58754788286 degrees up; backspin
  // 0.0897679694969 r / I = 229.019423891 rad/s (2187 rpm).
  const double loft = 10.5 * M_PI / 180;
  const ClubSpec club = driver();
  const ImpactFace face{{40, 0, 0},
                        {std::cos(loft), 0, std::sin(loft)},
                        club.head_mass,
                        club.restitution,
                        club.friction};
  const ImpactResult r = club_impact(resting_ball(), face);
  EXPECT_NEAR(r.velocity.norm(), 58.564934897037794, 1e-9);
  EXPECT_NEAR(std::atan2(r.velocity.z(), r.velocity.x()) * 180 / M_PI, 8.587547882862474, 1e-9);
  EXPECT_NEAR(r.velocity.y(), 0, 1e-12);
  EXPECT_NEAR(r.spin.y(), -229.01942389103476, 1e-6) << "backspin: the top turning back";
  EXPECT_NEAR(r.impulse.dot(face.normal), 2.688389156754353, 1e-9);
}

TEST(ClubImpact, FrictionCapsTheSpinOfAGlancingBlow) {
  // A face lofted 60 degrees: the slip is large, the normal impulse small: the impulse along the
  // face is friction x the normal one, and the ball still slides.
  const double loft = 60 * M_PI / 180;
  const ClubSpec club = driver();
  const ImpactFace face{
      {10, 0, 0}, {std::cos(loft), 0, std::sin(loft)}, club.head_mass, club.restitution, 0.1};
  const ImpactResult r = club_impact(resting_ball(), face);
  const double normal = r.impulse.dot(face.normal);
  EXPECT_NEAR((r.impulse - normal * face.normal).norm(), 0.1 * normal, 1e-12);
}

TEST(ClubImpact, APartingFaceGivesNothing) {
  const ImpactFace face{{-5, 0, 0}, {1, 0, 0}, 0.2, 0.83, 0.8};
  const ImpactResult r = club_impact(resting_ball(), face);
  EXPECT_EQ(r.velocity, Eigen::Vector3d::Zero());
  EXPECT_EQ(r.impulse, Eigen::Vector3d::Zero());
}

}  // namespace
}  // namespace olympics::sports::golf
