// The javelin's field and referee by sequences of steps: the mark from the arc along the line
// to its centre, the sector, tip first, the arc (official); the seed's stages and its x measure
// (paper); the seed's reward terms on hand-computed states.
#include "javelin/javelin_referee.h"

#include <gtest/gtest.h>

#include <cmath>

#include "javelin/javelin_rewards.h"
#include "javelin/javelin_sport.h"
#include "registry.h"

namespace olympics::sports::javelin {
namespace {

// Official rules with the arc's inner edge 2 m from the start mark: the centre at x = -6.
JavelinRules official() {
  JavelinRules r;
  r.official = true;
  r.attempt_s = 60;
  return r;
}

ThrowingArea field() {
  const JavelinRules r = official();
  return {{r.run_up - r.arc_radius, 0.0}, r.arc_radius, r.half_sector_rad(), 2.0};
}

ThrowStep holding(double t) {
  ThrowStep s;
  s.t = t;
  s.held = true;
  return s;
}

ThrowStep flying(double t) {
  ThrowStep s;
  s.t = t;
  s.javelin_centre = {20, 0, 8};
  s.hand_distance = 10;
  return s;
}

ThrowStep landing(double t, const Eigen::Vector3d& tip, bool head_only) {
  ThrowStep s = flying(t);
  s.javelin_ground = true;
  s.head_only = head_only;
  s.tip_touch = tip;
  return s;
}

TEST(ThrowingArea, TheSectorLinesPassThroughTheArcsEndsOnTheRunwayLines) {
  const ThrowingArea a = field();
  // 28.96 degrees: the sector's lines cut the 8 m arc 2 m either side of the axis, where the
  // 4 m runway's lines meet it (TR 32.9, 32.10).
  EXPECT_NEAR(a.radius * std::sin(a.half_angle), 2.0, 1e-3);
}

TEST(ThrowingArea, TheMarkIsFromTheArcsInnerEdgeAlongTheLineToTheCentreRoundedDown) {
  const ThrowingArea a = field();
  // On the axis: 44 - (-6) = 50 m from the centre, 42 m from the arc.
  EXPECT_DOUBLE_EQ(a.mark({44.0, 0.0, 0.0}), 42.00);
  // Off the axis, along the line to the centre: (30, 9) is sqrt(36^2 + 9^2) = 37.1079 m from
  // (-6, 0): 29.1079 m from the arc, recorded as 29.10 (down to the whole centimetre).
  EXPECT_DOUBLE_EQ(a.mark({30.0, 9.0, 0.0}), 29.10);
  EXPECT_TRUE(a.in_sector({30.0, 9.0, 0.0}));   // atan(9 / 36) = 14.04 degrees < 14.48
  EXPECT_FALSE(a.in_sector({30.0, 9.5, 0.0}));  // atan(9.5 / 36) = 14.78 degrees
  EXPECT_FALSE(a.in_sector({1.9, 0.0, 0.0})) << "inside the arc";
  EXPECT_TRUE(a.beyond_arc({2.0, 0.0, 0.0})) << "the arc's inner edge itself";
  EXPECT_FALSE(a.beyond_arc({1.99, 0.0, 0.0}));
  EXPECT_TRUE(a.outside_runway({0.0, -2.0, 0.0}));
  EXPECT_FALSE(a.outside_runway({0.0, 1.99, 0.0}));
}

TEST(JavelinReferee, ATipFirstLandingInsideTheSectorIsMeasured) {
  JavelinReferee ref(official(), field(), 0.0);
  EXPECT_FALSE(ref.step(holding(0.5)));
  EXPECT_FALSE(ref.step(flying(0.6)));
  EXPECT_TRUE(ref.released());
  const auto r = ref.step(landing(2.5, {30.0, 9.0, 0.0}, true));
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->valid);
  EXPECT_DOUBLE_EQ(r->mark, 29.10);
  EXPECT_FALSE(ref.step(landing(2.6, {30.0, 9.0, 0.0}, true))) << "decided once";
}

TEST(JavelinReferee, AFlatLandingIsInvalid) {
  JavelinReferee ref(official(), field(), 0.0);
  ref.step(flying(0.6));
  const auto r = ref.step(landing(2.5, {44.0, 0.0, 0.0}, false));  // the shaft touched too
  ASSERT_TRUE(r);
  EXPECT_FALSE(r->valid);
  EXPECT_EQ(r->reason, "flat");
}

TEST(JavelinReferee, OutsideTheSectorOrInsideTheArcIsInvalid) {
  for (const Eigen::Vector3d& tip : {Eigen::Vector3d(30.0, 9.5, 0.0), Eigen::Vector3d(1.5, 0, 0)}) {
    JavelinReferee ref(official(), field(), 0.0);
    ref.step(flying(0.6));
    const auto r = ref.step(landing(2.5, tip, true));
    ASSERT_TRUE(r);
    EXPECT_FALSE(r->valid);
    EXPECT_EQ(r->reason, "sector") << tip.transpose();
  }
}

TEST(JavelinReferee, TouchingTheArcOrARunwayLineBeforeTheLandingIsAFoul) {
  {
    JavelinReferee ref(official(), field(), 0.0);
    ref.step(flying(0.6));
    ThrowStep s = flying(0.7);
    s.athlete_beyond_arc = true;  // stepped on the arc while the javelin flies
    const auto r = ref.step(s);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->reason, "arc");
  }
  {
    JavelinReferee ref(official(), field(), 0.0);
    ref.step(flying(0.6));
    ThrowStep s = landing(2.5, {44.0, 0.0, 0.0}, true);
    s.athlete_beyond_arc = true;  // on the landing's own step: before the landing is decided
    EXPECT_EQ(ref.step(s)->reason, "arc");
  }
  {
    JavelinReferee ref(official(), field(), 0.0);
    ThrowStep s = holding(0.3);
    s.athlete_outside_runway = true;  // a foot on a runway line, the javelin still held
    EXPECT_EQ(ref.step(s)->reason, "runway");
  }
}

TEST(JavelinReferee, AFallBeforeTheReleaseAndTheTimeAreFouls) {
  JavelinReferee ref(official(), field(), 0.0);
  ThrowStep s = holding(1.0);
  s.down = true;
  EXPECT_EQ(ref.step(s)->reason, "fell");
  JavelinReferee slow(official(), field(), 0.0);
  EXPECT_FALSE(slow.step(holding(59.9)));
  EXPECT_EQ(slow.step(holding(60.1))->reason, "time");
}

TEST(JavelinReferee, PaperEndsByStageAndMeasuresXWhereTheJavelinComesDown) {
  const JavelinRules paper;  // hold < 20 ticks, throw < 40, then flight
  {
    JavelinReferee ref(paper, field(), 0.0);
    ThrowStep s = flying(0.3);
    s.tick = 10;  // let go in the hold stage
    EXPECT_EQ(ref.step(s)->reason, "dropped");
  }
  {
    JavelinReferee ref(paper, field(), 0.0);
    ThrowStep s = holding(0.3);
    s.tick = 10;
    s.attitude_error = 50 * M_PI / 180;
    EXPECT_EQ(ref.step(s)->reason, "strayed");
  }
  {
    JavelinReferee ref(paper, field(), 0.0);
    ThrowStep s = holding(1.4);
    s.tick = 41;
    s.hand_distance = 0.1;  // still in the hand in the flight stage
    EXPECT_EQ(ref.step(s)->reason, "not_thrown");
  }
  {
    JavelinReferee ref(paper, field(), 0.0);
    ThrowStep s = flying(1.0);
    s.tick = 30;  // released in the throw stage
    EXPECT_FALSE(ref.step(s));
    s.tick = 70;
    s.javelin_centre = {18.4, 0.3, 0.29};  // its centre below 0.3 m: the mark is its x
    s.javelin_ground = true;               // no tip-first check in the seed's
    const auto r = ref.step(s);
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->valid);
    EXPECT_DOUBLE_EQ(r->mark, 18.4);
  }
}

// Eq. 7 as SMPLOlympics' code has it, on states computed by hand.
TEST(JavelinRewards, EachTermIsTheSeedsOnAHandComputedState) {
  JavelinRewardState s;
  s.stage = Stage::Hold;
  s.cord = {0.1, -0.7, 1.4};
  s.hand = {0.1, -0.7, 1.5};        // 0.1 m
  s.cord_start = {0.1, -0.4, 1.0};  // 0.5 m from the cord
  s.attitude_error = 0.2;
  s.velocity = {0, 0, -2};
  s.spin = {0, 1, 0};
  auto t = javelin_reward_terms(s);
  EXPECT_FLOAT_EQ(t[0], std::exp(-0.1f));
  EXPECT_FLOAT_EQ(t[1], 0.7 * std::exp(-0.5) + 0.2 * std::exp(-0.2) + 0.05 * std::exp(-2.0) +
                            0.05 * std::exp(-1.0));
  for (int i = 2; i < kJavelinTerms; ++i) EXPECT_EQ(t[i], 0.0f) << i;

  s.stage = Stage::Throw;
  s.cord = {0.9, -0.7, 1.9};
  s.hand = {0.5, -0.7, 1.6};  // 0.5 m apart
  s.root_offset = {0.3, -0.4};
  s.x_prev = 1.0, s.x = 2.5;  // 1.5 m nearer x = 50
  t = javelin_reward_terms(s);
  EXPECT_EQ(t[0], 0.0f);
  EXPECT_EQ(t[1], 0.0f);
  EXPECT_FLOAT_EQ(t[2], 1.5 / 5);
  EXPECT_FLOAT_EQ(t[3], std::exp(-(0.09 + 0.16) / 2));
  EXPECT_FLOAT_EQ(t[4], 0.5f);
  EXPECT_EQ(t[5], 0.0f);

  s.stage = Stage::Flight;
  s.x_prev = 49.0, s.x = 55.0;  // past the target: |50 - x| grew, clamped at 0
  s.heading_err = 0.1;
  t = javelin_reward_terms(s);
  EXPECT_EQ(t[2], 0.0f);
  EXPECT_EQ(t[3], 0.0f);
  EXPECT_EQ(t[4], 0.0f);
  EXPECT_FLOAT_EQ(t[5], std::exp(-10 * 0.01));
  s.x_prev = 10.0, s.x = 20.0;  // 10 m nearer in a tick: clamped at 1
  EXPECT_FLOAT_EQ(javelin_reward_terms(s)[2], 1.0f);

  // The weights: 0.1 x 0.9 and 0.1 x 0.1 in the hold stage, 0.9, 0.05, 0.05, 0.1.
  const auto terms = javelin_rewards();
  const std::vector<double> weights = {0.09, 0.01, 0.9, 0.05, 0.05, 0.1};
  ASSERT_EQ(terms.size(), weights.size());
  for (size_t i = 0; i < terms.size(); ++i) EXPECT_DOUBLE_EQ(terms[i].weight, weights[i]);
}

}  // namespace
}  // namespace olympics::sports::javelin

namespace olympics::sports::javelin {
namespace {

TEST(JavelinRules, PaperIsTheSeedsStandingThrowOfficialTheMensJavelinOnA30mRunway) {
  const auto& sport = dynamic_cast<const JavelinSport&>(sport_or_throw("javelin"));
  const JavelinRules paper = sport.rules(nlohmann::json::object());
  EXPECT_FALSE(paper.official);
  EXPECT_DOUBLE_EQ(paper.javelin.mass, 2.45);
  EXPECT_DOUBLE_EQ(paper.javelin.length, 2.70);
  EXPECT_FALSE(paper.aerodynamics);
  EXPECT_EQ(paper.hold_ticks, 20);
  EXPECT_EQ(paper.throw_ticks, 40);
  EXPECT_EQ(paper.attempts, 1);
  const JavelinRules official = sport.rules({{"rules", "official"}});
  EXPECT_TRUE(official.official);
  EXPECT_DOUBLE_EQ(official.javelin.mass, 0.8);
  EXPECT_GE(official.javelin.length, 2.60);
  EXPECT_LE(official.javelin.length, 2.70);
  EXPECT_GE(official.javelin.tip_to_com, 0.90);
  EXPECT_LE(official.javelin.tip_to_com, 1.06);
  EXPECT_DOUBLE_EQ(official.javelin.tip_to_grip, official.javelin.tip_to_com) << "cord over it";
  EXPECT_TRUE(official.aerodynamics);
  EXPECT_DOUBLE_EQ(official.run_up, 30.0);
  EXPECT_EQ(official.attempts, 3);
  EXPECT_DOUBLE_EQ(official.attempt_s, 60.0);
  EXPECT_DOUBLE_EQ(sport.rules({{"rules", "official"}, {"run_up", 2.0}}).run_up, 2.0)
      << "a setting beside the preset wins";
  EXPECT_THROW(sport.rules({{"run_up", 50}}), std::invalid_argument);
}

}  // namespace
}  // namespace olympics::sports::javelin
