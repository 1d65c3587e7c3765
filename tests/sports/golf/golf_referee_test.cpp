// Golf's referees as logic: strokes counted (one per club contact, a double hit within one stroke
// counted once), holed, at rest, out of bounds (stroke and distance), the maximum score; and the
// seed's episode: its success rule (the ball stops within 1 m of the target) and endings.
#include "golf/golf_referee.h"

#include <gtest/gtest.h>

namespace olympics::sports::golf {
namespace {

GolfRules official() {
  GolfRules r;
  r.official = true;
  r.max_strokes = 3;
  r.hole_s = 60;
  return r;
}

GolfTick at(double t) {
  GolfTick s;
  s.t = t;
  s.tick = static_cast<int>(t * 30);
  s.target = {2, 0, 0};
  return s;
}

GolfTick touch(double t) {
  GolfTick s = at(t);
  s.club_touch = true;
  s.club_touch_t = t;
  s.ball_speed = 1.5;
  return s;
}

TEST(GolfReferee, EachClubContactIsAStrokeAndADoubleHitCountsOnce) {
  HoleReferee ref(official());
  EXPECT_EQ(ref.step(at(0.5)), GolfCall::None) << "no contact, no stroke";
  EXPECT_EQ(ref.step(touch(1.0)), GolfCall::Stroke);
  EXPECT_EQ(ref.strokes(), 1);
  EXPECT_TRUE(ref.struck());
  EXPECT_EQ(ref.step(touch(1.1)), GolfCall::None) << "struck twice in one stroke (Rule 10.1a)";
  EXPECT_EQ(ref.strokes(), 1);
  // The ball slows and comes to rest: after kAtRestS below kAtRestSpeed.
  GolfTick slow = at(3.0);
  EXPECT_EQ(ref.step(slow), GolfCall::None);
  slow.t = 3.0 + kAtRestS + 0.01;
  EXPECT_EQ(ref.step(slow), GolfCall::AtRest);
  EXPECT_FALSE(ref.struck());
  EXPECT_EQ(ref.step(touch(5.0)), GolfCall::Stroke);
  EXPECT_EQ(ref.strokes(), 2);
  GolfTick in = at(6.0);
  in.holed = true;
  EXPECT_EQ(ref.step(in), GolfCall::Holed);
  EXPECT_TRUE(ref.over());
  EXPECT_TRUE(ref.holed());
  EXPECT_EQ(ref.score(), 2);
  EXPECT_EQ(ref.step(touch(7.0)), GolfCall::None) << "the hole is over";
  EXPECT_EQ(ref.strokes(), 2);
}

TEST(GolfReferee, OutOfBoundsCostsAStrokeAndTheMaximumEndsTheHole) {
  HoleReferee ref(official());  // max 3
  EXPECT_EQ(ref.step(touch(1.0)), GolfCall::Stroke);
  GolfTick out = at(2.0);
  out.out_of_bounds = true;
  out.ball_speed = 1.0;
  EXPECT_EQ(ref.step(out), GolfCall::OutOfBounds);
  EXPECT_EQ(ref.penalties(), 1);
  EXPECT_EQ(ref.score(), 2);
  EXPECT_EQ(ref.step(touch(4.0)), GolfCall::Stroke);  // 2 strokes + 1 penalty = the maximum
  GolfTick rest = at(5.0);
  ref.step(rest);
  rest.t = 5.5;
  EXPECT_EQ(ref.step(rest), GolfCall::PickedUp);
  EXPECT_EQ(ref.picked_up_reason(), "max_strokes");
  EXPECT_EQ(ref.score(), 3);
  EXPECT_FALSE(ref.holed());
}

TEST(GolfReferee, TheTimeRunningOutScoresTheMaximum) {
  HoleReferee ref(official());
  EXPECT_EQ(ref.step(at(60.5)), GolfCall::PickedUp);
  EXPECT_EQ(ref.picked_up_reason(), "time");
  EXPECT_EQ(ref.score(), 3);
}

GolfTick seed_tick(int tick, Eigen::Vector3d ball, Eigen::Vector3d prev, double speed) {
  GolfTick s;
  s.tick = tick;
  s.ball = ball;
  s.ball_prev = prev;
  s.ball_speed = speed;
  s.target = {0, -5, 0};
  return s;
}

TEST(GolfSeedReferee, SuccessIsTheBallStoppingWithin1mOfTheTarget) {
  SeedReferee ref;
  GolfTick hit = seed_tick(3, {0.02, -0.3, 0.02}, {0, 0, 0.02}, 3.0);
  hit.seed_contact = true;
  EXPECT_FALSE(ref.step(hit));
  EXPECT_TRUE(ref.contact());
  EXPECT_FALSE(ref.step(seed_tick(10, {0.05, -3.0, 0.02}, {0.05, -2.9, 0.02}, 1.0)));
  const auto end = ref.step(seed_tick(20, {0.05, -4.2, 0.02}, {0.05, -4.19, 0.02}, 0.05));
  ASSERT_TRUE(end);
  EXPECT_EQ(end->reason, "ball_stopped");
  EXPECT_TRUE(end->hit);
  EXPECT_NEAR(end->stop_distance, std::hypot(0.05, 0.8, 0.02), 1e-12);
  EXPECT_TRUE(end->success());

  SeedReferee short_of_it;
  short_of_it.step(hit);
  const auto miss = short_of_it.step(seed_tick(20, {0.05, -3.9, 0.02}, {0.05, -3.89, 0.02}, 0.05));
  ASSERT_TRUE(miss);
  EXPECT_GT(miss->stop_distance, 1.0);
  EXPECT_FALSE(miss->success()) << "1.1 m short is no success";
}

TEST(GolfSeedReferee, TheSeedsEndings) {
  SeedReferee early;
  GolfTick down = seed_tick(1, {0, 0, 0.02}, {0, 0, 0.02}, 0);
  down.down = true;
  EXPECT_FALSE(early.step(down)) << "nothing ends before the third tick";
  EXPECT_EQ(early.step(seed_tick(2, {0, 0, 0.02}, {0, 0, 0.02}, 0)), std::nullopt);
  SeedReferee idle;
  EXPECT_FALSE(idle.step(seed_tick(60, {0, 0, 0.02}, {0, 0, 0.02}, 0)));
  const auto none = idle.step(seed_tick(61, {0, 0, 0.02}, {0, 0, 0.02}, 0));
  ASSERT_TRUE(none);
  EXPECT_EQ(none->reason, "no_contact");
  EXPECT_FALSE(none->hit);
  SeedReferee back;
  EXPECT_EQ(back.step(seed_tick(5, {-0.06, 0, 0.02}, {0, 0, 0.02}, 1))->reason, "no_contact");
  SeedReferee away;
  GolfTick hit = seed_tick(5, {0.02, -0.2, 0.02}, {0, 0, 0.02}, 2);
  hit.seed_contact = true;
  away.step(hit);
  EXPECT_EQ(away.step(seed_tick(6, {0.02, 0.1, 0.02}, {0.02, -0.2, 0.02}, 2))->reason,
            "ball_not_closer");
  SeedReferee near;
  GolfTick close = seed_tick(5, {0, 0, 0.02}, {0, 0, 0.02}, 0);
  close.body_near_ball = true;
  EXPECT_EQ(near.step(close)->reason, "ball_near_body");
}

}  // namespace
}  // namespace olympics::sports::golf
