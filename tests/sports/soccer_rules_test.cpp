// The soccer rules without physics (what is a goal, who restarts and where, kick-offs, halves),
// and the rewards computed by hand on built states.
#include <gtest/gtest.h>

#include <cmath>

#include "soccer/field.h"
#include "soccer/soccer_referee.h"
#include "soccer/soccer_rewards.h"

namespace olympics::sports::soccer {
namespace {

constexpr double kR = 0.110;  // the ball's radius (Law 2: 68-70 cm round)

TEST(SoccerField, AGoalIsTheWholeBallOverTheWholeLineBetweenThePostsAndUnderTheBar) {
  Field f;  // goal lines from x = +-16 to +-16.12 (as deep as the posts), goal 4 m by 2 m
  int end = 0;
  const double line = 16.0 + 2 * f.post_radius;  // the goal line's far edge
  EXPECT_EQ(f.goal_line_outer(), line);
  EXPECT_EQ(f.crossed({16.0, 0, 0.5}, kR), Crossed::None) << "centre on the line";
  EXPECT_EQ(f.crossed({16.0 + kR + 0.05, 0, 0.5}, kR), Crossed::None)
      << "past the field's edge but not past the whole line (the posts' depth): no goal yet";
  EXPECT_EQ(f.crossed({line + kR, 0, 0.5}, kR), Crossed::None) << "touching the line's far edge";
  EXPECT_EQ(f.crossed({line + kR + 1e-6, 0, 0.5}, kR, &end), Crossed::Goal);
  EXPECT_EQ(end, 1);
  EXPECT_EQ(f.crossed({-16.3, 1.9, 1.9}, kR, &end), Crossed::Goal);
  EXPECT_EQ(end, -1);
  // Wide of a post (centre outside the posts' inner edge) or over the bar: out, no goal.
  EXPECT_EQ(f.crossed({16.3, 2.01, 0.5}, kR), Crossed::GoalLine);
  EXPECT_EQ(f.crossed({16.3, 0, 2.05}, kR), Crossed::GoalLine);
  EXPECT_EQ(f.crossed({16.2, 3.0, 0.1}, kR), Crossed::None) << "wide, not over the whole line";
  EXPECT_EQ(f.crossed({3, 10.0 + kR, 0.1}, kR), Crossed::None) << "on the touch line";
  EXPECT_EQ(f.crossed({3, -10.2, 0.1}, kR), Crossed::TouchLine);
}

class RefereeTest : public ::testing::Test {
 protected:
  // 2v2: slots 0, 1 team 0 (attacking +x in the first half), slots 2, 3 team 1.
  Field field;
  SoccerRules rules;
  SoccerReferee ref{field, rules, {0, 0, 1, 1}, kR};
  void SetUp() override { ref.start(0, 0.0); }
};

TEST_F(RefereeTest, TheKickOffIsPlayedByTheKickingSide) {
  ASSERT_TRUE(ref.pending());
  EXPECT_EQ(ref.pending()->kind, RestartKind::KickOff);
  ref.touch(0, 0.5);
  EXPECT_FALSE(ref.pending()) << "in play";
  EXPECT_FALSE(ref.update({0.3, 0, kR}, 0.6));
}

TEST_F(RefereeTest, AGoalNamesScorerAndAssistAndTheConcedingSideKicksOff) {
  ref.touch(0, 0.5);
  ref.touch(1, 1.0);
  auto s = ref.update({16.3, 0.5, 0.4}, 1.5);
  ASSERT_TRUE(s && s->goal);
  EXPECT_EQ(s->reason, "goal");
  EXPECT_EQ(s->goal->team, 0);
  EXPECT_EQ(s->goal->scorer, 1);
  EXPECT_EQ(s->goal->assist, 0);
  EXPECT_FALSE(s->goal->own_goal);
  EXPECT_EQ(ref.score()[0], 1);
  EXPECT_EQ(s->restart.kind, RestartKind::KickOff);
  EXPECT_EQ(s->restart.team, 1);
  // An opponent's touch between breaks the assist; a defender's last touch is an own goal.
  ref.touch(2, 2.0);
  ref.touch(0, 2.5);
  ref.touch(3, 3.0);
  s = ref.update({16.3, 0, 0.4}, 3.1);
  ASSERT_TRUE(s && s->goal);
  EXPECT_EQ(s->goal->team, 0);
  EXPECT_EQ(s->goal->scorer, 3);
  EXPECT_TRUE(s->goal->own_goal);
  EXPECT_EQ(s->goal->assist, -1);
  EXPECT_EQ(ref.score()[0], 2);
}

TEST_F(RefereeTest, OverATouchLineTheOtherSideThrowsInWhereTheBallLeft) {
  ref.touch(0, 0.5);
  ref.touch(2, 1.0);  // team 1 touched it last
  auto s = ref.update({4.2, 10.2, 0.1}, 1.2);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->reason, "out");
  EXPECT_EQ(s->line, "touch");
  EXPECT_EQ(s->last_touch, 2);
  EXPECT_EQ(s->restart.kind, RestartKind::ThrowIn);
  EXPECT_EQ(s->restart.team, 0);
  EXPECT_NEAR(s->restart.spot.x(), 4.2, 1e-12);
  EXPECT_NEAR(s->restart.spot.y(), 10 - kR, 1e-12);
}

TEST(SoccerReferee, AFreeKickInsteadOfAThrowInAsASetting) {
  Field field;
  SoccerRules rules;
  rules.touch_free_kick = true;
  SoccerReferee ref(field, rules, {0, 1}, kR);
  ref.start(1, 0);
  ref.touch(1, 0.2);
  auto s = ref.update({-3, -10.3, 0.1}, 0.5);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->restart.kind, RestartKind::FreeKick);
  EXPECT_EQ(s->restart.team, 0);
  EXPECT_NEAR(s->restart.spot.y(), -9.0, 1e-12) << "1 m inside";
}

TEST_F(RefereeTest, OverAGoalLineTheLastTouchDecidesGoalKickOrCorner) {
  ref.touch(0, 0.5);  // an attacker of the +x goal touched it last: goal kick for team 1
  auto s = ref.update({16.4, 5.0, 0.1}, 1.0);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->line, "goal");
  EXPECT_EQ(s->restart.kind, RestartKind::GoalKick);
  EXPECT_EQ(s->restart.team, 1);
  EXPECT_NEAR(s->restart.spot.x(), 16 - Field::kGoalArea, 1e-12);
  ref.touch(2, 1.5);  // the goal kick, taken
  ref.touch(3, 2.0);  // a defender's last touch over its own goal line: corner for team 0
  s = ref.update({16.4, -3.0, 0.5}, 2.5);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->restart.kind, RestartKind::Corner);
  EXPECT_EQ(s->restart.team, 0);
  EXPECT_NEAR(s->restart.spot.x(), 16 - kR, 1e-12);
  EXPECT_NEAR(s->restart.spot.y(), -(10 - kR), 1e-12) << "the corner on the ball's side";
}

TEST_F(RefereeTest, AnOpponentWhoPlaysARestartFirstHasItTakenAgain) {
  ref.touch(2, 0.3);  // team 0 kicks off; team 1 touched first
  auto s = ref.update({0.2, 0, kR}, 0.4);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->reason, "encroachment");
  EXPECT_EQ(s->culprit, 2);
  EXPECT_EQ(s->restart.kind, RestartKind::KickOff);
  EXPECT_EQ(s->restart.team, 0);
  ASSERT_TRUE(ref.pending());
}

TEST_F(RefereeTest, ARestartNobodyTakesIsInPlayAfterTheTimeout) {
  EXPECT_FALSE(ref.update({0, 0, kR}, rules.restart_timeout_s - 0.1));
  EXPECT_TRUE(ref.pending());
  EXPECT_FALSE(ref.update({0, 0, kR}, rules.restart_timeout_s + 0.1));
  EXPECT_FALSE(ref.pending());
  ref.touch(2, 11);
  EXPECT_FALSE(ref.update({0.1, 0, kR}, 11.1)) << "a touch by either side is play now";
}

TEST_F(RefereeTest, AtHalfTimeTheTeamsChangeEndsAndTheOtherSideKicksOff) {
  EXPECT_EQ(ref.attack_direction(0), 1);
  ref.touch(0, 1);
  auto s = ref.update({1, 1, kR}, rules.half_s);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->reason, "half_time");
  EXPECT_EQ(s->restart.kind, RestartKind::KickOff);
  EXPECT_EQ(s->restart.team, 1);
  EXPECT_EQ(ref.half(), 1);
  EXPECT_EQ(ref.attack_direction(0), -1);
  EXPECT_EQ(ref.attack_direction(1), 1);
  // Now team 1 scores at +x.
  ref.touch(3, rules.half_s + 1);
  s = ref.update({16.5, 0, 0.3}, rules.half_s + 2);
  ASSERT_TRUE(s && s->goal);
  EXPECT_EQ(s->goal->team, 1);
  EXPECT_FALSE(ref.update({0, 0, kR}, 2 * rules.half_s)) << "no third half";
}

// ---- Rewards, by hand.

RewardState state() {
  RewardState s;
  s.root_before = {0, 0, 0.9};
  s.root = {0.1, 0, 0.9};
  s.ball_before = {3, 0, kR};
  s.ball = {3.2, 0, kR};
  s.ball_velocity = {6, 0, 0};
  s.target = {16, 0, 1.0};
  s.attack = 1;
  return s;
}

TEST(SoccerRewards, TermsByHand) {
  const RewardState s = state();
  EXPECT_NEAR(player_to_ball(s), 3.2 - 3.1, 1e-12);
  const double before = std::hypot(13.0, 1.0 - kR), after = std::hypot(12.8, 1.0 - kR);
  EXPECT_NEAR(ball_to_goal(s), before - after, 1e-12);
  EXPECT_NEAR(ball_velocity_to_goal(s), 6 * 12.8 / after, 1e-12);
  // Entry in the goal plane after t = 12.8 / 6 s of flight: z = r - g t^2 / 2 (below ground is
  // still a point of the plane: the reward only measures the distance).
  Eigen::Vector3d e;
  ASSERT_TRUE(entry_point(s, e));
  const double t = 12.8 / 6;
  EXPECT_NEAR(e.x(), 16, 1e-12);
  EXPECT_NEAR(e.z(), kR - 0.5 * 9.81 * t * t, 1e-9);
  EXPECT_NEAR(ball_to_target(s), std::exp(-(e - s.target).squaredNorm()), 1e-12);
  RewardState away = s;
  away.ball_velocity = {-1, 0, 0};
  EXPECT_EQ(ball_to_target(away), 0.0) << "not flying towards the goal";
  // No dribble: the root 2 m past the spot at x = -1.
  RewardState past = s;
  past.root = {1, 0, 0.9};
  EXPECT_NEAR(no_dribble(past, {-1, 0, kR}), 1 - std::exp(-0.2 * 4), 1e-12);
  EXPECT_EQ(no_dribble(past, {5, 0, kR}), 0.0) << "not yet past the spot";
}

TEST(SoccerRewards, ThePenaltyKickIsStagedByWhetherTheBallNearsTheGoal) {
  const RewardState moving = state();  // the ball nears the goal: g > 0
  const auto m = penalty_kick_terms(moving, {5, 0, kR}, false);
  EXPECT_EQ(m[0], 0.0f) << "player_to_ball off";
  EXPECT_FLOAT_EQ(m[1], static_cast<float>(ball_to_goal(moving)));
  EXPECT_FLOAT_EQ(m[2], static_cast<float>(ball_velocity_to_goal(moving)));
  EXPECT_FLOAT_EQ(m[3], static_cast<float>(ball_to_target(moving)));
  RewardState still = moving;  // the ball at rest: g = 0
  still.ball_before = still.ball;
  still.ball_velocity.setZero();
  const auto r = penalty_kick_terms(still, {5, 0, kR}, true);
  EXPECT_FLOAT_EQ(r[0], static_cast<float>(player_to_ball(still)));
  EXPECT_EQ(r[1], 0.0f);
  EXPECT_EQ(r[2], 0.0f);
  EXPECT_EQ(r[3], 0.0f);
  EXPECT_EQ(r[5], 1.0f) << "goal";
  // The seed's weights: 0.4, 0.1, 0.1, 0.8, -1 (goal and fallen weigh 0).
  const auto terms = penalty_kick_rewards();
  ASSERT_EQ(terms.size(), 7u);
  EXPECT_EQ(terms[0].weight, 0.4);
  EXPECT_EQ(terms[3].weight, 0.8);
  EXPECT_EQ(terms[4].weight, -1.0);
  EXPECT_EQ(terms[5].weight, 0.0);
}

TEST(SoccerRewards, AStillBallsJitterDoesNotSwitchTheStage) {
  // A ball lying still moves by sub-micrometres from tick to tick; towards the goal, that is
  // g > 0 by a hair. The stage must stay "go to the ball".
  RewardState jitter = state();
  jitter.ball_before = jitter.ball;
  jitter.ball.x() += 3e-7;  // 0.3 micrometre towards the goal
  jitter.ball_velocity = {1e-5, 0, 0};
  ASSERT_GT(ball_to_goal(jitter), 0.0);
  const auto t = penalty_kick_terms(jitter, {5, 0, kR}, false);
  EXPECT_FLOAT_EQ(t[0], static_cast<float>(player_to_ball(jitter))) << "player_to_ball on";
  EXPECT_NE(t[0], 0.0f);
  EXPECT_EQ(t[1], 0.0f);
  EXPECT_EQ(t[3], 0.0f);
  // A ball rolling towards the goal at 1 cm/s is past the dead band: the kick stage.
  RewardState rolling = jitter;
  rolling.ball.x() = rolling.ball_before.x() + 0.01 / 30;
  EXPECT_EQ(penalty_kick_terms(rolling, {5, 0, kR}, false)[0], 0.0f);
}

TEST(SoccerRewards, TeamPlayPaysTheGoalToOneSideAndChargesTheOther) {
  RewardState s = state();
  s.fallen = true;
  const auto scored = team_play_terms(s, 1), conceded = team_play_terms(s, -1);
  EXPECT_EQ(scored[3], 1.0f);
  EXPECT_EQ(conceded[3], -1.0f);
  EXPECT_FLOAT_EQ(scored[0], static_cast<float>(player_to_ball(s)));
  EXPECT_EQ(scored[4], 1.0f) << "fallen";
  EXPECT_EQ(team_play_rewards()[3].name, "goal");
}

}  // namespace
}  // namespace olympics::sports::soccer
