// A full-swing driver in a golf match: the head moving at 40 m/s passes 0.33 m per 120 Hz
// physics step, seven times the ball's and its own thickness; the match must still find the
// strike (golf/swept_strike.h) and launch the ball as the impact model says, worked out here
// from the head's velocity and face: reduced mass, (1 + e) along the face normal, friction along
// the face up to rolling. The athlete is moved by hand: every body of it translating at 40 m/s
// (a rigid slide keeps its joints still) along the unlofted face's normal, so that the lofted
// face meets the ball 10.5 degrees off its path, as a driver does; the ball at rest in the head's
// path (at the head's height: the zero action holds the arm out level, the club with it). On
// main's code the head passed through the ball: it fell at 0.33 m/s, no stroke.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "../athletics/field_event_session.h"
#include "golf/golf_match.h"
#include "golf/golf_sport.h"

namespace olympics::sports::golf {
namespace {

using Session = athletics::FieldEventSession<GolfMatch, GolfSport>;

TEST(GolfDriver, AHeadAtFortyMetresPerSecondLaunchesARestingBallAsTheImpactModelSays) {
  Session s("golf", "solo", {{"play", "official"}, {"club", "driver"}, {"distance", 30}});
  GolfMatch& m = *s.match;
  ASSERT_EQ(m.rules().club.name, "driver");
  const ClubSpec club = m.rules().club;
  const core::BodyState hand = m.athlete(0).body_state(m.hand_body());
  const Eigen::Quaterniond face_q =
      hand.orientation *
      Eigen::Quaterniond(Eigen::AngleAxisd(club.loft_deg * M_PI / 180, Eigen::Vector3d::UnitZ()));
  const Eigen::Vector3d n = face_q * Eigen::Vector3d::UnitX();  // the face's normal
  // The head's path: level, along the unlofted face's normal (the loft turns the face 10.5
  // degrees off the path, as a driver's face looks up from a level swing).
  const Eigen::Vector3d unlofted = hand.orientation * Eigen::Vector3d::UnitX();
  const Eigen::Vector3d along = Eigen::Vector3d(unlofted.x(), unlofted.y(), 0).normalized();
  ASSERT_GT(std::acos(std::clamp(n.dot(along), -1.0, 1.0)) * 180 / M_PI, 9.0)
      << "the face looks off the path by about the loft";
  const Eigen::Vector3d head_v = 40.0 * along;
  // The ball at rest 0.12 m in front of the face, on the head's path.
  const double r = m.ball(0).spec().radius;
  const Eigen::Vector3d ball0 = m.club_head(0) + (club.head_half.x() + r + 0.12) * along;
  m.ball(0).set_state(ball0, Eigen::Vector3d::Zero());
  athletics::give_velocity(m.athlete(0), head_v);
  s.step();  // one tick: four physics steps, the head passing the ball in the first

  // The impact model by hand, for this face and head velocity.
  const double mass = m.ball(0).spec().mass, inertia = 0.4 * mass * r * r;
  const double reduced = mass * club.head_mass / (mass + club.head_mass);
  const double normal_impulse = (1 + club.restitution) * reduced * head_v.dot(n);
  const Eigen::Vector3d head_t = head_v - head_v.dot(n) * n;  // down the face
  const double along_face =
      std::min(club.friction * normal_impulse, head_t.norm() / (1 / reduced + r * r / inertia));
  const Eigen::Vector3d expected = (normal_impulse * n + along_face * head_t.normalized()) / mass;
  // Launch angle: off the head's path (towards the face normal's side).
  auto launch_deg = [&](const Eigen::Vector3d& v) {
    return std::acos(std::clamp(v.normalized().dot(along), -1.0, 1.0)) * 180 / M_PI;
  };
  const Eigen::Vector3d v = m.ball(0).velocity();
  // Drag (16 m/s^2 at 58 m/s) and gravity over the rest of the tick: < 1% and < 0.3 degrees.
  EXPECT_NEAR(v.norm(), expected.norm(), 0.015 * expected.norm())
      << "ball speed; the head at 40 m/s, expected smash factor " << expected.norm() / 40;
  EXPECT_NEAR(launch_deg(v), launch_deg(expected), 0.5);
  EXPECT_GT(v.normalized().dot(n), std::cos(launch_deg(expected) * M_PI / 180) - 0.01)
      << "launched on the face's side of the path";
  EXPECT_GT(v.dot(along), 50.0) << "the ball flies on along the swing";
  for (int i = 0; i < 3; ++i) s.step();
  EXPECT_EQ(m.hole_referee(0).strokes(), 1) << "the strike is a stroke";
}

// The same swing twice, on a sloping green: bit for bit the same ball and athlete afterwards.
TEST(GolfDriver, TheSweptStrikeIsDeterministic) {
  std::vector<double> runs[2];
  for (auto& state : runs) {
    Session s("golf", "solo",
              {{"play", "official"}, {"club", "driver"}, {"distance", 5}, {"green_slope", 2}});
    GolfMatch& m = *s.match;
    const core::BodyState hand = m.athlete(0).body_state(m.hand_body());
    const Eigen::Vector3d x = hand.orientation * Eigen::Vector3d::UnitX();
    const Eigen::Vector3d along = Eigen::Vector3d(x.x(), x.y(), 0).normalized();
    m.ball(0).set_state(m.club_head(0) + 0.2 * along, Eigen::Vector3d::Zero());
    athletics::give_velocity(m.athlete(0), 40.0 * along);
    for (int i = 0; i < 30; ++i) s.step();
    ASSERT_EQ(m.hole_referee(0).strokes(), 1);
    for (const Eigen::Vector3d& v :
         {m.ball(0).position(), m.ball(0).velocity(), m.ball(0).angular_velocity(),
          m.athlete(0).body_state(m.hand_body()).position})
      state.insert(state.end(), v.data(), v.data() + 3);
  }
  EXPECT_EQ(runs[0], runs[1]);
}

}  // namespace
}  // namespace olympics::sports::golf
