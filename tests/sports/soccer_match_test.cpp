// Soccer matches in process: goals and outs found from the ball's physics, restarts carried out
// (the ball on its spot, players back in their halves for a kick-off, opponents kept away from a
// restart), the penalty kick's end, and the scripted baseline scoring a penalty and a goal.
#include "soccer/soccer_match.h"

#include <gtest/gtest.h>

#include "core/control_rate.h"
#include "policies.h"
#include "registry.h"
#include "zero_play.h"

namespace olympics::sports::soccer {
namespace {

std::unique_ptr<SportMatch> make(const std::string& mode, std::uint64_t seed,
                                 const nlohmann::json& options = {}) {
  return sport_or_throw("soccer").create({mode, seed, 0.0, options});
}

SoccerMatch& soccer(std::unique_ptr<SportMatch>& m) { return dynamic_cast<SoccerMatch&>(*m); }

Eigen::Vector3d root(SportMatch& m, int slot) {
  const SoccerMatch& s = dynamic_cast<SoccerMatch&>(m);
  return s.scene().humanoid(slot).body_state(0).position;
}

TEST(SoccerMatch, ABallIntoTheGoalScoresAndTheConcedingSideKicksOffFromItsHalf) {
  auto m = make("2v2", 4);
  SoccerMatch& s = soccer(m);
  step_zero(*m);
  // A shot into the goal that team 0 attacks.
  const int end = s.referee().attack_direction(0);
  s.ball().set_state({end * 14.0, 0.5, 0.5}, {end * 15.0, 0, 0.5});
  nlohmann::json goal;
  for (int t = 0; t < 30 && goal.is_null(); ++t) {
    const nlohmann::json events = step_zero(*m);
    if (const auto* e = find_call(events, "goal")) goal = *e;
  }
  ASSERT_FALSE(goal.is_null()) << "no goal within a second";
  EXPECT_EQ(goal["team"], 0);
  EXPECT_FALSE(goal.contains("slot")) << "nobody touched it: no scorer";
  EXPECT_EQ(m->outcome().scores[0], 1.0f);
  EXPECT_EQ(m->outcome().info["score"]["text"], "1-0");
  // Kick-off for team 1: the ball on the centre spot, everyone in its own half.
  ASSERT_TRUE(s.referee().pending());
  EXPECT_EQ(s.referee().pending()->kind, RestartKind::KickOff);
  EXPECT_EQ(s.referee().pending()->team, 1);
  EXPECT_LT(s.ball().position().head<2>().norm(), 1e-9);
  for (int slot = 0; slot < 4; ++slot) {
    const int d = s.referee().attack_direction(m->team_of(slot));
    EXPECT_LT(d * root(*m, slot).x(), 0) << "slot " << slot << " in its own half";
  }
  // The kick-off's observation flag: +1 for team 1, -1 for team 0.
  const auto layout = client::ObservationLayout::from_blocks(m->layout().observation);
  std::vector<float> o(m->obs_size());
  m->observe(2, o);
  EXPECT_EQ(o[layout.offset("match", "restart")], 1.0f);
  EXPECT_EQ(o[layout.offset("match", "their_goals")], 1.0f);
  m->observe(0, o);
  EXPECT_EQ(o[layout.offset("match", "restart")], -1.0f);
  EXPECT_EQ(o[layout.offset("match", "my_goals")], 1.0f);
}

// Goals are judged every physics step, as basketball's baskets: a ball wholly over the line for
// part of a tick (here: coming back out of the goal fast, as off a stanchion or a keeper's hand)
// has scored, although at the tick's end it is back in play.
TEST(SoccerMatch, ABallOverTheLineForPartOfATickIsAGoal) {
  auto m = make("2v2", 4);
  SoccerMatch& s = soccer(m);
  step_zero(*m);
  const int end = s.referee().attack_direction(0);
  const double over = s.field().goal_line_outer() + s.ball().spec().radius;
  // 0.25 m over the line's far edge, coming out at 15 m/s: 0.125 m per 120 Hz step, so still
  // over after the first step and back in play after the tick's four.
  s.ball().set_state({end * (over + 0.25), 0, 0.5}, {-end * 15.0, 0, 0});
  const nlohmann::json events = step_zero(*m);
  EXPECT_NE(find_call(events, "goal"), nullptr) << events.dump();
  EXPECT_EQ(m->outcome().scores[0], 1.0f);
}

// The whole ball over the whole goal line: past the field's edge by its radius but not past the
// posts' depth is no goal yet (all 26 scripted penalty goals used to be given 1-50 mm into it).
TEST(SoccerMatch, ABallNotYetPastThePostsDepthIsNoGoal) {
  auto m = make("penalty_kick", 1);
  SoccerMatch& s = soccer(m);
  const double r = s.ball().spec().radius, edge = s.field().half_length();
  s.ball().set_state({edge + r + 0.06, 0, 0.5}, Eigen::Vector3d::Zero());  // held there
  const nlohmann::json events = step_zero(*m);
  EXPECT_EQ(find_call(events, "goal"), nullptr);
  EXPECT_FALSE(m->outcome().match_over);
}

TEST(SoccerMatch, AShotOffThePostIsNoGoal) {
  auto m = make("1v1", 2);
  SoccerMatch& s = soccer(m);
  const Field& f = s.field();
  // Straight at the post's centre line, hard: it rebounds into the field.
  const double post_y = f.goal_width / 2 + f.post_radius;
  s.ball().set_state({f.half_length() - 3, post_y, 1.0}, {30, 0, 0});
  for (int t = 0; t < 10; ++t) {
    const nlohmann::json events = step_zero(*m);
    EXPECT_EQ(find_call(events, "goal"), nullptr);
  }
  EXPECT_LT(s.ball().velocity().x(), 0) << "bounced back off the post";
  EXPECT_EQ(m->outcome().scores[0] + m->outcome().scores[1], 0.0f);
}

TEST(SoccerMatch, OverATouchLineTheRestartIsPlacedAndOpponentsKeptAway) {
  auto m = make("1v1", 5, {{"restart_distance", 3.0}});
  SoccerMatch& s = soccer(m);
  step_zero(*m);
  // Nobody has touched it: team 0 restarts at the touch line; team 1's player stands there.
  const Eigen::Vector3d at = root(*m, 1);
  s.ball().set_state({at.x(), 9.8, s.ball().spec().radius}, {0, 3, 0});
  nlohmann::json restart;
  for (int t = 0; t < 30 && restart.is_null(); ++t) {
    const auto events = step_zero(*m);
    if (const auto* e = find_call(events, "restart")) {
      restart = *e;
      ASSERT_NE(find_call(events, "out"), nullptr);
      EXPECT_EQ((*find_call(events, "out"))["line"], "touch");
    }
  }
  ASSERT_FALSE(restart.is_null());
  EXPECT_EQ(restart["kind"], "throw_in");
  EXPECT_EQ(restart["team"], 0);
  EXPECT_NEAR(s.ball().position().y(), 10 - s.ball().spec().radius, 1e-9);
  const Eigen::Vector2d spot = s.ball().position().head<2>();
  for (int slot = 0; slot < 2; ++slot) {
    if (m->team_of(slot) != 1) continue;
    EXPECT_GE((root(*m, slot).head<2>() - spot).norm(), 3.0) << "opponent kept away";
  }
}

TEST(SoccerMatch, APenaltyKickEndsWithTheGoalOrAMiss) {
  auto m = make("penalty_kick", 1);
  SoccerMatch& s = soccer(m);
  EXPECT_NEAR(s.ball().position().x(), 16 - 11, 1e-9) << "on the spot";
  s.ball().set_state(s.ball().position(), {12, 0, 1});
  while (!m->outcome().match_over) step_zero(*m);
  EXPECT_EQ(m->outcome().reason, "goal");
  EXPECT_EQ(m->outcome().winner_team, 0);
  EXPECT_EQ(m->outcome().info["goals"].size(), 1u);
  EXPECT_EQ(m->outcome().terms[0][5], 1.0f) << "the goal term";

  auto wide = make("penalty_kick", 1);
  soccer(wide).ball().set_state(soccer(wide).ball().position(), {12, 4, 0});
  while (!wide->outcome().match_over) step_zero(*wide);
  EXPECT_EQ(wide->outcome().reason, "missed");
  EXPECT_EQ(wide->outcome().winner_team, -1);
}

// The scripted baseline plays the penalty kick for real: it walks the ball into the goal.
TEST(SoccerMatch, TheScriptedBaselineScoresAPenalty) {
  int goals = 0;
  for (std::uint64_t seed = 1; seed <= 8 && goals == 0; ++seed) {
    auto m = make("penalty_kick", seed);
    auto policy = client::make_policy("scripted", seed);
    policy->start({"soccer", "penalty_kick", core::kControlDt,
                   client::ObservationLayout::from_blocks(m->layout().observation),
                   m->action_size()});
    std::vector<float> o(m->obs_size()), a(m->action_size());
    bool touched = false;
    while (!m->outcome().match_over) {
      m->observe(0, o);
      policy->act(o, a);
      m->step({a});
      touched |= soccer(m).touched_this_tick(0);
    }
    EXPECT_TRUE(touched) << "seed " << seed;
    goals += m->outcome().reason == "goal";
  }
  EXPECT_GT(goals, 0);
}

}  // namespace
}  // namespace olympics::sports::soccer
