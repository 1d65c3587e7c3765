// Basketball team play in process: restarts carried out (the taker on its spot with the ball
// presented, the defenders kept off), touches sensed from the ball's contacts, a basket worth
// what the shooter's release spot says, out of bounds, the shot clock and the game's end.
#include <gtest/gtest.h>

#include <random>

#include "basketball/basketball_match.h"
#include "registry.h"
#include "zero_play.h"

namespace olympics::sports::basketball {
namespace {

using Eigen::Vector3d;

std::unique_ptr<SportMatch> game(const std::string& mode, std::uint64_t seed,
                                 const nlohmann::json& options = {}) {
  return sport_or_throw("basketball").create({mode, seed, 0.0, options});
}

BasketballMatch& basketball(std::unique_ptr<SportMatch>& m) {
  return dynamic_cast<BasketballMatch&>(*m);
}

Vector3d root(const BasketballMatch& b, int slot) {
  return b.scene().humanoid(slot).body_state(0).position;
}

// Puts the ball against `slot`'s pelvis and plays a tick: the contact is that player's touch.
void touch_with(BasketballMatch& b, int slot) {
  b.ball().set_state(root(b, slot), Vector3d::Zero());
  step_zero(b);
  ASSERT_EQ(b.referee().last_touch(), slot) << "the ball against its pelvis is its touch";
}

// The events of zero-action ticks until `call` is made (at most `ticks`).
nlohmann::json play_until(SportMatch& m, const std::string& call, int ticks) {
  nlohmann::json events = nlohmann::json::array();
  for (int t = 0; t < ticks && !find_call(events, call) && !m.outcome().match_over; ++t)
    for (const auto& e : step_zero(m)) events.push_back(e);
  return events;
}

TEST(BasketballGame, TheGameStartsWithACheckBallPresentedToTheTakerAndTheDefenceKeptOff) {
  for (const std::string mode : {"1v1", "2v2"}) {
    auto m = game(mode, 5);
    BasketballMatch& b = basketball(m);
    const int side = b.referee().possession();
    ASSERT_GE(side, 0);
    EXPECT_TRUE(b.referee().cleared());
    EXPECT_TRUE(b.presenting());
    const Vector3d spot = b.present_spot();
    EXPECT_TRUE(b.court().behind_arc(spot.head<2>())) << mode << ": the check ball is at the arc";
    int taker = -1;
    for (int s = 0; s < m->slot_count(); ++s)
      if ((root(b, s) - spot).head<2>().norm() < BasketballMatch::kPresentForward + 0.2) taker = s;
    ASSERT_GE(taker, 0) << mode << ": somebody stands at the ball";
    EXPECT_EQ(m->team_of(taker), side);
    for (int s = 0; s < m->slot_count(); ++s) {
      if (m->team_of(s) == side) continue;
      EXPECT_GT((root(b, s) - root(b, taker)).head<2>().norm(), 1.8) << mode << " slot " << s;
    }
    // The taker's observation: my ball, cleared, presented to me; the defence's: theirs.
    std::vector<float> obs(m->obs_size());
    const auto game = [&](const char* field) { return field_offset(*m, "game", field); };
    m->observe(taker, obs);
    EXPECT_EQ(obs[game("possession")], 1.0f);
    EXPECT_EQ(obs[game("cleared")], 1.0f);
    EXPECT_EQ(obs[game("presented_to_me")], 1.0f);
    EXPECT_NEAR(obs[game("shot_clock")], 12.0f, 1e-6);
    const int defender = m->team_of(0) == side ? m->slot_count() - 1 : 0;
    m->observe(defender, obs);
    EXPECT_EQ(obs[game("possession")], -1.0f);
    EXPECT_EQ(obs[game("presented_to_me")], 0.0f);
    // Held still while presented, then free.
    play_zero(*m, 10);
    EXPECT_LT((b.ball().position() - spot).norm(), 1e-9);
  }
}

TEST(BasketballGame, ABasketFromATouchBehindTheArcIsWorthTwoAndTheOtherSideTakesItUnderTheBasket) {
  auto m = game("1v1", 7, {{"present_s", 0.1}});
  BasketballMatch& b = basketball(m);
  const int shooter = b.referee().possession() == m->team_of(0) ? 0 : 1;
  play_zero(*m, 4);  // past the presentation
  touch_with(b, shooter);
  ASSERT_TRUE(b.court().behind_arc(root(b, shooter).head<2>()));
  b.ball().set_state({0, 0, 3.5}, {0, 0, -1});  // dropping through the rim
  const auto events = play_until(*m, "basket", 30);
  const auto* basket = find_call(events, "basket");
  ASSERT_NE(basket, nullptr);
  EXPECT_EQ((*basket)["slot"], shooter);
  EXPECT_EQ((*basket)["points"], 2);
  EXPECT_EQ(m->outcome().scores[m->team_of(shooter)], 2.0f);
  // The reward's points term: +2 to the shooter's side, -2 to the other, on that tick.
  const int points = 3;  // term index in team_play_rewards()
  ASSERT_EQ(m->reward_terms()[points], "points");
  EXPECT_EQ(m->outcome().terms[shooter][points], 2.0f);
  EXPECT_EQ(m->outcome().terms[1 - shooter][points], -2.0f);
  const auto* restart = find_call(events, "restart");
  ASSERT_NE(restart, nullptr);
  EXPECT_EQ((*restart)["kind"], "after_basket");
  EXPECT_EQ((*restart)["team"], m->team_of(1 - shooter));
  EXPECT_EQ(b.referee().possession(), m->team_of(1 - shooter));
  EXPECT_FALSE(b.referee().cleared()) << "after a basket the ball must be cleared";
  EXPECT_FALSE(b.court().behind_arc(root(b, 1 - shooter).head<2>())) << "taken under the basket";

  // Its put-back without clearing does not count.
  play_zero(*m, 4);
  touch_with(b, 1 - shooter);
  b.ball().set_state({0, 0, 3.5}, {0, 0, -1});
  const auto again = play_until(*m, "not_cleared", 30);
  ASSERT_NE(find_call(again, "not_cleared"), nullptr);
  EXPECT_EQ(find_call(again, "basket"), nullptr);
  EXPECT_EQ(m->outcome().scores[m->team_of(1 - shooter)], 0.0f);
}

TEST(BasketballGame, TheBallOnTheFloorOutsideTheLinesIsTheOtherSidesCheckBall) {
  auto m = game("1v1", 9, {{"present_s", 0.1}});
  BasketballMatch& b = basketball(m);
  const int toucher = b.referee().possession() == m->team_of(0) ? 0 : 1;
  play_zero(*m, 4);
  touch_with(b, toucher);
  b.ball().set_state({-4, -b.court().width / 2 - 0.5, 0.3}, Vector3d::Zero());
  const auto events = play_until(*m, "out", 30);
  const auto* out = find_call(events, "out");
  ASSERT_NE(out, nullptr);
  EXPECT_EQ((*out)["last_touch_slot"], toucher);
  const auto* restart = find_call(events, "restart");
  ASSERT_NE(restart, nullptr);
  EXPECT_EQ((*restart)["kind"], "check_ball");
  EXPECT_EQ((*restart)["team"], m->team_of(1 - toucher));
  EXPECT_TRUE(b.presenting());
}

TEST(BasketballGame, TheShotClockGivesTheBallAwayWhenItRunsOut) {
  auto m = game("1v1", 10, {{"shot_clock_s", 3}});
  BasketballMatch& b = basketball(m);
  const int side = b.referee().possession();
  const auto events = play_until(*m, "shot_clock", 120);
  const auto* call = find_call(events, "shot_clock");
  ASSERT_NE(call, nullptr);
  EXPECT_NEAR((*call)["t"].get<double>(), 3.0, 0.05);
  EXPECT_EQ((*call)["team"], side);
  EXPECT_EQ(b.referee().possession(), 1 - side);
}

TEST(BasketballGame, TheGameEndsWhenASideReachesThePointsToWin) {
  auto m = game("1v1", 11, {{"present_s", 0.1}, {"points_to_win", 2}});
  BasketballMatch& b = basketball(m);
  const int shooter = b.referee().possession() == m->team_of(0) ? 0 : 1;
  play_zero(*m, 4);
  touch_with(b, shooter);
  b.ball().set_state({0, 0, 3.5}, {0, 0, -1});
  play_zero(*m, 30);
  ASSERT_TRUE(m->outcome().match_over);
  EXPECT_EQ(m->outcome().winner_team, m->team_of(shooter));
  EXPECT_EQ(m->outcome().reason, "points_reached");
  EXPECT_EQ(m->outcome().info["baskets"].size(), 1u);
}

// Random actions for every slot for up to `ticks`; every tick's events.
nlohmann::json play_random(SportMatch& m, int ticks) {
  std::mt19937_64 rng(3);
  std::normal_distribution<float> noise(0, 1);
  std::vector<std::vector<float>> actions(m.slot_count(), std::vector<float>(m.action_size()));
  nlohmann::json events = nlohmann::json::array();
  for (int t = 0; t < ticks && !m.outcome().match_over; ++t) {
    std::vector<std::span<const float>> spans;
    for (auto& a : actions) {
      for (float& x : a) x = noise(rng);
      spans.emplace_back(a);
    }
    m.step(spans);
    for (const auto& e : m.outcome().info["events"]) events.push_back(e);
  }
  return events;
}

TEST(BasketballGame, AFallenPlayerIsStoodUpAfterTwoSecondsUnlessFallsAreOnlyReported) {
  auto m = game("1v1", 5);
  const nlohmann::json events = play_random(*m, 8 * 30);
  const nlohmann::json* fall = find_call(events, "fall");
  const nlohmann::json* stood = find_call(events, "stood_up");
  ASSERT_NE(fall, nullptr) << "random players fall";
  ASSERT_NE(stood, nullptr);
  EXPECT_GE(stood->at("t").get<double>() - fall->at("t").get<double>(), 2.0 - 1e-9);

  auto reported = game("1v1", 5, {{"falls", "report"}});
  const nlohmann::json same = play_random(*reported, 8 * 30);
  EXPECT_NE(find_call(same, "fall"), nullptr);
  EXPECT_EQ(find_call(same, "stood_up"), nullptr);
}

TEST(BasketballGame, OnTheFullCourtPlayStartsAtTheCentreAndEachSideScoresOnItsOwnBasket) {
  auto m = game("1v1", 7, {{"court", "full"}, {"present_s", 0.1}});
  BasketballMatch& b = basketball(m);
  const Court& court = b.court();
  EXPECT_NEAR(b.present_spot().x(), court.centre_x(), BasketballMatch::kPresentForward + 0.2);
  // Each slot's "rim" is the basket its side attacks (distances do not depend on the frame).
  std::vector<float> obs(m->obs_size());
  const int rim = field_offset(*m, "rim", "centre");
  for (int s = 0; s < 2; ++s) {
    m->observe(s, obs);
    const double seen = Vector3d(obs[rim], obs[rim + 1], obs[rim + 2]).norm();
    EXPECT_NEAR(seen, (court.rim_centre(b.attacked_by(s)) - root(b, s)).norm(), 1e-4);
    EXPECT_EQ(b.attacked_by(s), m->team_of(s));
  }
  // The side attacking the far basket scores there: 3, released from mid-court.
  const int far_side = 1, shooter = m->team_of(0) == far_side ? 0 : 1;
  play_zero(*m, 4);
  touch_with(b, shooter);
  ASSERT_TRUE(court.behind_arc(root(b, shooter).head<2>(), 1));
  b.ball().set_state(court.rim_centre(1) + Vector3d(0, 0, 0.5), {0, 0, -1});
  const auto events = play_until(*m, "basket", 30);
  const auto* basket = find_call(events, "basket");
  ASSERT_NE(basket, nullptr);
  EXPECT_EQ((*basket)["team"], far_side);
  EXPECT_EQ((*basket)["points"], 3);
  EXPECT_EQ(m->outcome().scores[far_side], 3.0f);
  const auto* restart = find_call(events, "restart");
  ASSERT_NE(restart, nullptr);
  EXPECT_EQ((*restart)["kind"], "throw_in");
  EXPECT_EQ((*restart)["team"], 1 - far_side);
}

}  // namespace
}  // namespace olympics::sports::basketball
