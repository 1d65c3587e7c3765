// Hurdles in process: an official hurdle overturns under a push between 3.6 and 4 kgf; an
// athlete who knocks a hurdle over is not disqualified (official) but ends the seed's run
// (paper); a foot outside the lane disqualifies; an 8-athlete race ranks all eight.
#include "hurdles/hurdles_match.h"

#include <gtest/gtest.h>

#include <random>

#include "../athletics/field_event_session.h"
#include "hurdles/hurdle.h"
#include "hurdles/hurdles_sport.h"

namespace olympics::sports::hurdles {
namespace {

using Session = athletics::FieldEventSession<HurdlesMatch, HurdlesSport>;
using athletics::give_velocity;

constexpr double kKgf = 9.81;  // N

const nlohmann::json kOfficial = {{"rules", "official"}};

// Every event of the next `ticks` ticks (or to the end).
std::vector<nlohmann::json> events_over(Session& r, int ticks) {
  std::vector<nlohmann::json> all;
  for (int i = 0; i < ticks && !r.match->outcome().match_over; ++i) {
    r.step();
    for (const auto& e : r.match->outcome().info["events"]) all.push_back(e);
  }
  return all;
}

int count_calls(const std::vector<nlohmann::json>& events, const std::string& call) {
  return static_cast<int>(std::count_if(
      events.begin(), events.end(), [&](const nlohmann::json& e) { return e["call"] == call; }));
}

// A lone hurdle pushed horizontally at the centre of its top bar with `kgf` for `seconds`.
bool overturns_under(const HurdlesRules& rules, double kgf, double seconds = 3.0) {
  core::PhysicsWorld world;
  Hurdle hurdle(world, rules, 0.0, 0.0);
  const double dt = 1.0 / 120;
  for (int i = 0; i < 30; ++i) world.step(dt);  // settle on the ground
  for (int i = 0; i < seconds / dt && !hurdle.knocked_over(); ++i) {
    const Eigen::Vector3d top = hurdle.top_centre();
    dBodyAddForceAtPos(hurdle.body(), kgf * kKgf, 0, 0, top.x(), top.y(), top.z());
    world.step(dt);
  }
  return hurdle.knocked_over();
}

TEST(Hurdle, APushOf36KgfHoldsAnd4KgfOverturnsIt) {
  for (const char* race : {"110m", "100m"}) {
    const HurdlesRules rules = HurdlesSport().rules({{"rules", "official"}, {"race", race}});
    EXPECT_NEAR(tipping_force_kgf(hurdle_parts(rules), rules.hurdle_height), 3.8, 1e-9) << race;
    EXPECT_FALSE(overturns_under(rules, 3.6)) << race << ": TR 22.3 asks at least 3.6 kgf";
    EXPECT_TRUE(overturns_under(rules, 4.0)) << race << ": and at most 4 kgf";
  }
  EXPECT_THROW(HurdlesSport().rules({{"tip_force", 3.5}}), std::invalid_argument);
}

TEST(Hurdle, StandsStillUntouched) {
  const HurdlesRules rules = HurdlesSport().rules(kOfficial);
  core::PhysicsWorld world;
  Hurdle hurdle(world, rules, 13.72, 0.0);
  for (int i = 0; i < 240; ++i) world.step(1.0 / 120);
  EXPECT_FALSE(hurdle.knocked_over());
  EXPECT_NEAR(hurdle.top_centre().z(), rules.hurdle_height, 0.005);
  EXPECT_NEAR(hurdle.top_centre().x(), 13.72, 0.005);
}

// The athlete launched at the first hurdle from 0.7 m before it.
Session run_into_the_first_hurdle(const nlohmann::json& options) {
  Session r("hurdles", "solo", options);
  core::Humanoid& h = r.match->athlete(0);
  h.reset({{r.match->rules().hurdle_x(0) - 0.7, 0, 0}, 0});
  give_velocity(h, {2.5, 0, 0});
  return r;
}

TEST(HurdlesMatch, OfficialKnockingAHurdleOverIsNoFoul) {
  Session r = run_into_the_first_hurdle(kOfficial);
  const auto events = events_over(r, 60);
  EXPECT_EQ(count_calls(events, "knocked"), 1) << "the first hurdle went over";
  EXPECT_TRUE(r.match->hurdle(0, 0).knocked_over());
  EXPECT_EQ(r.match->knocked(0), 1);
  EXPECT_EQ(count_calls(events, "disqualified"), 0);
  EXPECT_FALSE(r.match->result(0).has_value()) << "still racing";
}

TEST(HurdlesMatch, PaperTouchingTheWallEndsTheRun) {
  Session r = run_into_the_first_hurdle(nlohmann::json::object());
  const auto e = r.wait_for("did_not_finish", 60);
  ASSERT_FALSE(e.is_null());
  EXPECT_EQ(e["reason"], "touched_hurdle");
}

TEST(HurdlesMatch, AFootOutsideTheLaneDisqualifiesAndTheCentreDoesNot) {
  Session inside("hurdles", "solo", kOfficial);
  inside.match->athlete(0).reset({{5.0, 0.0, 0}, 0});
  EXPECT_TRUE(inside.wait_for("disqualified", 20).is_null());
  Session outside("hurdles", "solo", kOfficial);
  outside.match->athlete(0).reset({{5.0, 0.55, 0}, 0});  // the left foot over the lane's line
  const auto e = outside.wait_for("disqualified", 5);
  ASSERT_FALSE(e.is_null());
  EXPECT_EQ(e["reason"], "left_lane");
}

TEST(HurdlesMatch, AnEightAthleteRaceRanksAllEight) {
  Session r("hurdles", "competition_8", {{"rules", "official"}, {"get_up_s", 1.0}});
  HurdlesMatch& m = *r.match;
  // Four launched at the finish from different distances, one over its lane's line, three left
  // standing at the start (they fall and stay down).
  const double behind[4] = {0.9, 0.5, 1.3, 0.7};
  for (int slot = 0; slot < 4; ++slot) {
    core::Humanoid& h = m.athlete(slot);
    h.reset({{m.rules().race_m - behind[slot], m.lane_y(slot), 0}, 0});
    give_velocity(h, {3.0, 0, 0});
  }
  m.athlete(4).reset({{5.0, m.lane_y(4) + 0.55, 0}, 0});
  const auto events = events_over(r, 900);
  ASSERT_TRUE(m.outcome().match_over);
  EXPECT_EQ(m.outcome().reason, "race_complete");
  EXPECT_EQ(count_calls(events, "finish"), 4);
  EXPECT_EQ(count_calls(events, "disqualified"), 1);
  EXPECT_EQ(count_calls(events, "did_not_finish"), 3);
  for (int slot = 0; slot < 4; ++slot) ASSERT_TRUE(m.result(slot)->finished()) << slot;
  EXPECT_LT(m.result(1)->time, m.result(3)->time);
  EXPECT_LT(m.result(3)->time, m.result(0)->time);
  EXPECT_LT(m.result(0)->time, m.result(2)->time);
  EXPECT_EQ(m.outcome().info["places"], (std::vector<int>{3, 1, 4, 2, 5, 5, 5, 5}));
  EXPECT_EQ(m.outcome().winner_team, 1);
  EXPECT_FLOAT_EQ(m.outcome().scores[1], static_cast<float>(m.result(1)->time));
  EXPECT_EQ(m.outcome().scores[4], 0.0f);
}

}  // namespace
}  // namespace olympics::sports::hurdles

namespace olympics::sports::hurdles {
namespace {

TEST(HurdlesRules, PaperIsTheSeedsAndOfficialTheRulebooks) {
  const HurdlesSport sport;
  const HurdlesRules paper = sport.rules(nlohmann::json::object());
  EXPECT_FALSE(paper.official);
  EXPECT_FALSE(paper.free_hurdles) << "the seed's fixed walls";
  EXPECT_DOUBLE_EQ(paper.lane_spacing, 2.0);
  EXPECT_DOUBLE_EQ(paper.start_x, 0.0);
  EXPECT_DOUBLE_EQ(paper.hurdle_x(0), 13.72);
  EXPECT_NEAR(paper.hurdle_x(9), 95.98, 1e-9) << "the seed's hurdle_location";
  const HurdlesRules official = sport.rules(kOfficial);
  EXPECT_TRUE(official.official);
  EXPECT_TRUE(official.free_hurdles);
  EXPECT_DOUBLE_EQ(official.lane_spacing, 1.22);
  EXPECT_DOUBLE_EQ(official.race_m, 110.0);
  const HurdlesRules women = sport.rules({{"rules", "official"}, {"race", "100m"}});
  EXPECT_DOUBLE_EQ(women.race_m, 100.0);
  EXPECT_DOUBLE_EQ(women.hurdle_height, 0.838);
  EXPECT_DOUBLE_EQ(women.hurdle_x(0), 13.0);
  EXPECT_NEAR(women.hurdle_x(9), 89.5, 1e-9) << "10.50 m from the last hurdle to the line";
}

// Same seed and actions, same race, free hurdles included (they sleep and wake by the state).
TEST(HurdlesMatch, OfficialRacesReplayBitForBit) {
  auto play = [] {
    Session r("hurdles", "competition_2", kOfficial);
    r.match->athlete(0).reset({{12.9, 0, 0}, 0});  // into the first hurdle, which wakes
    give_velocity(r.match->athlete(0), {2.5, 0, 0});
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-0.3f, 0.3f);
    std::vector<float> a(r.match->action_size());
    for (int t = 0; t < 60; ++t) {
      for (float& x : a) x = u(rng);
      r.match->step({a, a});
    }
    return std::make_pair(r.match->state_hash(), r.match->knocked(0));
  };
  const auto first = play(), second = play();
  EXPECT_EQ(first.first, second.first);
  EXPECT_EQ(first.second, 1) << "the first hurdle went over, so its sleep and wake were exercised";
}

}  // namespace
}  // namespace olympics::sports::hurdles
