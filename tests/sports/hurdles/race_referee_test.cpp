// The hurdles referee by sequences of steps (both rule sets), the places a race gives, and the
// seed's reward (eq. 3) on hand-computed states.
#include "hurdles/race_referee.h"

#include <gtest/gtest.h>

#include "hurdles/hurdles_rewards.h"
#include "hurdles/race_places.h"

namespace olympics::sports::hurdles {
namespace {

HurdlesRules official() {
  HurdlesRules r;
  r.official = true;
  r.free_hurdles = true;
  return r;
}

// A step at t running at x (torso front and root alike), dt 1/120 s.
RaceStep at(double t, double x_prev, double x) {
  RaceStep s;
  s.t = t, s.dt = 1.0 / 120;
  s.torso_front_x_prev = x_prev, s.torso_front_x = x;
  s.root_x_prev = x_prev - 0.1, s.root_x = x - 0.1;
  return s;
}

TEST(RaceReferee, TheTorsoAtTheLineFinishesTimedBetweenSteps) {
  RaceReferee ref(official());
  EXPECT_FALSE(ref.step(at(20.0, 109.90, 109.95)));
  // The torso reaches 110 a quarter of the way through the next step.
  const auto r = ref.step(at(20.0 + 1.0 / 120, 109.95, 110.15));
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->finished());
  EXPECT_DOUBLE_EQ(r->time, photo_finish_time(20.0 + 0.25 / 120));
  EXPECT_DOUBLE_EQ(r->time, 20.003) << "read to 1/1000 s, rounded up: 20.00208 -> 20.003";
  EXPECT_FALSE(ref.step(at(21.0, 110.2, 110.3))) << "decided once";
}

TEST(RaceReferee, OfficialLeavingTheLaneOrATrailLegBesideAHurdleDisqualifies) {
  RaceReferee lane(official()), trail(official());
  RaceStep s = at(3.0, 5.0, 5.01);
  s.outside_lane = true;
  const auto r = lane.step(s);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->kind, RaceResult::Kind::Disqualified);
  EXPECT_EQ(r->reason, "left_lane");
  s = at(3.0, 13.7, 13.75);
  s.trail_leg_beside = true;
  const auto t = trail.step(s);
  ASSERT_TRUE(t);
  EXPECT_EQ(t->kind, RaceResult::Kind::Disqualified);
  EXPECT_EQ(t->reason, "trail_leg");
}

TEST(RaceReferee, OfficialAFallIsNoFoulUntilTheAthleteStaysDown) {
  HurdlesRules rules = official();
  rules.get_up_s = 2.0;
  RaceReferee ref(rules);
  RaceStep s = at(1.0, 3.0, 3.0);
  s.down = true;
  EXPECT_FALSE(ref.step(s));
  s.t = 2.5;
  EXPECT_FALSE(ref.step(s)) << "1.5 s down";
  s.down = false, s.t = 2.6;
  EXPECT_FALSE(ref.step(s)) << "up again: the race goes on";
  s.down = true, s.t = 3.0;
  EXPECT_FALSE(ref.step(s));
  s.t = 5.0;
  const auto r = ref.step(s);
  ASSERT_TRUE(r) << "2 s down in a row";
  EXPECT_EQ(r->kind, RaceResult::Kind::DidNotFinish);
  EXPECT_EQ(r->reason, "fell");
}

TEST(RaceReferee, PaperEndsTheRunOnATouchAFallOrLeavingTheTrackAndFinishesByTheRoot) {
  const HurdlesRules paper;
  {
    RaceReferee ref(paper);
    RaceStep s = at(4.0, 13.6, 13.65);
    s.hurdle_touch = true;
    const auto r = ref.step(s);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->kind, RaceResult::Kind::DidNotFinish);
    EXPECT_EQ(r->reason, "touched_hurdle");
  }
  {
    RaceReferee ref(paper);
    RaceStep s = at(4.0, 5, 5.1);
    s.root_y = 0.81;
    EXPECT_EQ(ref.step(s)->reason, "left_track");
  }
  {
    RaceReferee ref(paper);
    RaceStep s = at(4.0, 5, 5.1);
    s.down = true;
    EXPECT_EQ(ref.step(s)->reason, "fell");
  }
  {
    RaceReferee ref(paper);
    EXPECT_FALSE(ref.step(at(30.0, 110.0, 110.05)))
        << "the torso is past, the root (0.1 m behind) not";
    const auto r = ref.step(at(30.5, 110.05, 110.2));
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->finished());
    EXPECT_DOUBLE_EQ(r->time, 30.5) << "the step the root passed 110 m";
  }
}

TEST(RacePlaces, FinishersByTimeTiesShareAndTheRestAreLast) {
  const std::vector<std::optional<RaceResult>> results = {
      RaceResult::finish(15.2), RaceResult::dq("left_lane"), RaceResult::finish(14.9),
      RaceResult::finish(15.2), RaceResult::dnf("fell"),     std::nullopt};
  EXPECT_EQ(race_places(results), (std::vector<int>{2, 4, 1, 2, 4, 4}));
}

TEST(HurdlesRewards, DistanceIsTheSeedsOnAHandComputedState) {
  const Eigen::Vector3d goal(110, 0, 1);
  // |(10,0,1)-G| = 100; |(10.6,0.8,1)-G| = sqrt(99.4^2 + 0.8^2) = 99.40322...
  const auto terms = hurdles_reward_terms({10, 0, 1}, {10.6, 0.8, 1}, goal);
  EXPECT_NEAR(terms[0], 100.0 - std::sqrt(99.4 * 99.4 + 0.64), 1e-5);
  EXPECT_FLOAT_EQ(hurdles_reward_terms({10, 0, 1}, {9, 0, 1}, goal)[0], 0.0f) << "clamped at 0";
  EXPECT_FLOAT_EQ(hurdles_reward_terms({10, 0, 1}, {13, 0, 1}, goal)[0], 1.0f) << "clamped at 1";
  const auto names = hurdles_rewards();
  ASSERT_EQ(names.size(), 1u);
  EXPECT_EQ(names[0].name, "distance");
  EXPECT_DOUBLE_EQ(names[0].weight, 1.0);
}

}  // namespace
}  // namespace olympics::sports::hurdles
