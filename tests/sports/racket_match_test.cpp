// Tennis and table-tennis matches as the server runs them: settings, equipment, determinism,
// and whole matches that reach a score.
#include "racket/racket_match.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/humanoid_assets.h"
#include "racket/racket_equipment.h"
#include "registry.h"

namespace olympics::sports::racket {
namespace {

std::unique_ptr<SportMatch> make(const std::string& sport, const std::string& mode,
                                 std::uint64_t seed, nlohmann::json options = {}) {
  return sport_or_throw(sport).create({mode, seed, 120.0, options});
}

// Plays with constant actions (slot 1 may get others); returns the state hash after `ticks`
// ticks (or the end).
std::uint64_t play(SportMatch& m, int ticks, float a, float slot1 = NAN) {
  std::vector<std::vector<float>> acts(m.slot_count(), std::vector<float>(69, a));
  if (m.slot_count() > 1 && !std::isnan(slot1)) acts[1].assign(69, slot1);
  std::vector<std::span<const float>> spans(acts.begin(), acts.end());
  for (int t = 0; t < ticks && !m.outcome().match_over; ++t) m.step(spans);
  return m.state_hash();
}

TEST(RacketSports, RegisteredWithModesAndSettings) {
  for (const char* name : {"tennis", "table_tennis"}) {
    const Sport& s = sport_or_throw(name);
    EXPECT_EQ(s.modes().names(), (std::vector<std::string>{"ball_return", "1v1", "2v2"}));
    EXPECT_EQ(make(name, "ball_return", 1)->slot_count(), 1);
    EXPECT_EQ(make(name, "2v2", 1)->slot_count(), 4);
    EXPECT_EQ(s.layout("1v1").observation_size(), make(name, "1v1", 1)->obs_size());
  }
}

TEST(RacketSports, BadSettingsAreRefusedWithTheKnownOnes) {
  try {
    make("tennis", "1v1", 1, {{"net_hieght", 0.9}});
    FAIL() << "accepted an unknown setting";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("net_height"), std::string::npos) << e.what();
  }
  EXPECT_THROW(make("tennis", "1v1", 1, {{"net_height", "high"}}), std::invalid_argument);
  EXPECT_THROW(make("tennis", "1v1", 1, {{"net_height", 7.0}}), std::invalid_argument);
  EXPECT_THROW(make("tennis", "1v1", 1, {{"format", "marathon"}}), std::invalid_argument);
  EXPECT_THROW(make("table_tennis", "3v3", 1), std::invalid_argument);
  EXPECT_NO_THROW(make("tennis", "1v1", 1, {{"net_height", 0.914}, {"format", "tiebreak"}}));
}

TEST(RacketSports, EquipmentAddsItsMassToTheHand) {
  core::ModelSpec bare = core::load_humanoid(core::HumanoidKind::Smpl);
  core::ModelSpec racket = bare, paddle = bare;
  equipment::attach_equipment(racket, tennis_racket());
  equipment::attach_equipment(paddle, table_tennis_paddle());
  core::PhysicsWorld world;
  core::Humanoid h0(world, bare), h1(world, racket), h2(world, paddle);
  // Handle 0.14 kg + head 0.42 kg; the paddle (0.08 kg) replaces the 0.16 kg hand box.
  EXPECT_NEAR(h1.total_mass() - h0.total_mass(), 0.141 + 0.424, 0.01);
  EXPECT_NEAR(h2.total_mass() - h0.total_mass(), 0.080 - 0.161, 0.01);
}

TEST(RacketSports, SameSeedAndActionsGiveBitIdenticalMatches) {
  for (const char* name : {"tennis", "table_tennis"}) {
    auto a = make(name, "1v1", 9), b = make(name, "1v1", 9), c = make(name, "1v1", 10);
    const auto ha = play(*a, 400, 0.05f), hb = play(*b, 400, 0.05f), hc = play(*c, 400, 0.05f);
    EXPECT_EQ(ha, hb) << name;
    EXPECT_NE(ha, hc) << name;
    EXPECT_EQ(a->outcome().info.dump(), b->outcome().info.dump());
  }
}

// Two identical zero-action players never break each other's serve (the receiver always loses,
// so a tie-break stays level); here slot 1 holds a pose it cannot stand in, and falls.
TEST(RacketSports, TiebreakMatchReachesAFinalScore) {
  auto m = make("tennis", "1v1", 3, {{"format", "tiebreak"}});
  play(*m, 30 * 120, 0.0f, 0.3f);
  ASSERT_TRUE(m->outcome().match_over);
  EXPECT_EQ(m->outcome().reason, "match_won");
  const auto& score = m->outcome().info.at("score");
  EXPECT_EQ(score.at("winner"), m->outcome().winner_team);
  EXPECT_EQ(m->outcome().scores[m->outcome().winner_team], 1.0f);
  EXPECT_GE(m->outcome().info.at("points").size(), 7u);
}

TEST(RacketSports, RewardTermsAreReportedByName) {
  auto m = make("table_tennis", "ball_return", 4);
  EXPECT_EQ(m->reward_terms(), (std::vector<std::string>{"racket", "contact", "landing", "hits"}));
  play(*m, 1, 0.0f);
  const auto& terms = m->outcome().terms[0];
  EXPECT_GT(terms[0], 0.0f);  // not struck yet: the racket term guides towards the ball
  EXPECT_EQ(terms[1], 0.0f);
  EXPECT_FLOAT_EQ(m->outcome().reward[0], terms[0] + terms[1] + terms[2] + terms[3]);
}

// `start: "serve"` with nobody swinging: every toss falls untouched. Tennis: a fault, the toss
// again, the double fault; table tennis (doubles): the fault loses the point. The server stands
// diagonally opposite the box it serves to, its partner on the other side.
TEST(RacketSports, ServedPointsAreTossedAndUnstruckTossesAreFaults) {
  for (const char* name : {"tennis", "table_tennis"}) {
    auto m = make(name, "2v2", 5, {{"start", "serve"}});
    std::vector<std::string> calls;
    std::vector<float> zero(69, 0.0f);
    std::vector<std::span<const float>> acts(m->slot_count(), zero);
    nlohmann::json first_point;
    for (int t = 0; t < 30 * 8 && first_point.is_null(); ++t) {
      m->step(acts);
      for (const auto& ev : m->outcome().info.value("events", nlohmann::json::array())) {
        calls.push_back(ev.at("call"));
        if (ev.at("call") == "fault") {
          EXPECT_EQ(ev.at("reason"), "not_struck");
        }
        if (ev.at("call") == "point") first_point = ev;
      }
    }
    ASSERT_FALSE(first_point.is_null()) << name;
    const bool tennis = std::string(name) == "tennis";
    const std::vector<std::string> expected =
        tennis ? std::vector<std::string>{"toss", "fault", "toss", "fault", "point"}
               : std::vector<std::string>{"toss", "fault", "point"};
    EXPECT_EQ(calls, expected) << name;
    EXPECT_EQ(first_point.at("reason"), tennis ? "double_fault" : "fault");
  }
  EXPECT_THROW(make("tennis", "1v1", 1, {{"start", "volley"}}), std::invalid_argument);
  // Ball return feeds every ball: a serve there is refused, saying which modes serve.
  try {
    make("table_tennis", "ball_return", 1, {{"start", "serve"}});
    ADD_FAILURE() << "start: serve in ball_return was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("Use mode 1v1 or 2v2"), std::string::npos) << e.what();
  }
}

// `start: "serve"`, 2v2: all four players fall on the same tick (a pose none can stand in).
// The let replays the same point: the same partner serves again (not the next point's server),
// and no point is called.
TEST(RacketSports, ServedBothSidesFellLetKeepsTheServer) {
  for (const auto& [name, a] : {std::pair{"tennis", 0.3f}, std::pair{"table_tennis", 1.0f}}) {
    auto m = make(name, "2v2", 1, {{"start", "serve"}});
    std::vector<float> pose(69, a);
    std::vector<std::span<const float>> acts(m->slot_count(), pose);
    std::vector<std::string> calls;
    std::vector<int> tossed_to;
    for (int t = 0; t < 30 * 2 && tossed_to.size() < 3; ++t) {
      m->step(acts);
      for (const auto& ev : m->outcome().info.value("events", nlohmann::json::array())) {
        if (ev.at("call") == "fall") continue;
        calls.push_back(ev.at("call"));
        if (ev.at("call") == "toss") tossed_to.push_back(ev.at("slot"));
        if (ev.at("call") == "let") {
          EXPECT_EQ(ev.at("reason"), "both sides fell") << name;
        }
      }
    }
    ASSERT_EQ(tossed_to.size(), 3u) << name;
    EXPECT_EQ(calls, (std::vector<std::string>{"toss", "let", "toss", "let", "toss"})) << name;
    EXPECT_EQ(tossed_to, std::vector<int>(3, tossed_to.front())) << name;
  }
}

// The feed (the default start), 2v2: all four players fall on the same tick. The let replays the
// point: the same partner is fed again (the let names it), not the partner whose turn the next
// point would be, and no point is called.
TEST(RacketSports, FedBothSidesFellLetFeedsTheSamePlayerAgain) {
  for (const auto& [name, a] : {std::pair{"tennis", 0.3f}, std::pair{"table_tennis", 1.0f}}) {
    auto m = make(name, "2v2", 1);
    std::vector<float> pose(69, a);
    std::vector<std::span<const float>> acts(m->slot_count(), pose);
    std::vector<int> fed_again;
    for (int t = 0; t < 30 * 3 && fed_again.size() < 3; ++t) {
      m->step(acts);
      for (const auto& ev : m->outcome().info.value("events", nlohmann::json::array())) {
        EXPECT_NE(ev.at("call"), "point") << name;
        if (ev.at("call") != "let") continue;
        EXPECT_EQ(ev.at("reason"), "both sides fell") << name;
        ASSERT_TRUE(ev.contains("slot")) << name << ": the let does not say who is fed again";
        fed_again.push_back(ev.at("slot"));
      }
    }
    ASSERT_EQ(fed_again.size(), 3u) << name;
    EXPECT_EQ(fed_again, std::vector<int>(3, fed_again.front())) << name;
  }
}

// `start: "serve"`, 2v2, nobody swinging: every serve is lost, so the serve changes hands by the
// rules alone. One partner serves the team's whole turn (tennis: a game of four points; table
// tennis: two points) and the four players serve in the order A1, B1, A2, B2 (ITF rule 14; ITTF
// 2.14): four turns by four different players, the teams alternating.
TEST(RacketSports, DoublesPartnersServeWholeTurnsInRotation) {
  for (const auto& [name, turn_points] : {std::pair{"tennis", 4}, std::pair{"table_tennis", 2}}) {
    auto m = make(name, "2v2", 3, {{"start", "serve"}});
    std::vector<float> zero(69, 0.0f);
    std::vector<std::span<const float>> acts(m->slot_count(), zero);
    std::vector<int> server_of_point, loser_of_point;  // slot that tossed; team that lost
    int tossed = -1;
    for (int t = 0; t < 30 * 60 && server_of_point.size() < 4u * turn_points; ++t) {
      m->step(acts);
      for (const auto& ev : m->outcome().info.value("events", nlohmann::json::array())) {
        if (ev.at("call") == "toss") tossed = ev.at("slot");
        if (ev.at("call") != "point") continue;
        server_of_point.push_back(tossed);
        loser_of_point.push_back(1 - ev.at("winner_team").get<int>());
      }
    }
    ASSERT_EQ(server_of_point.size(), 4u * turn_points) << name;
    std::set<int> turn_servers;
    for (int turn = 0; turn < 4; ++turn) {
      const int first = turn * turn_points;
      for (int p = first; p < first + turn_points; ++p) {
        EXPECT_EQ(server_of_point[p], server_of_point[first]) << name << " point " << p;
        EXPECT_EQ(loser_of_point[p], loser_of_point[first]) << name << " point " << p;
      }
      if (turn > 0) {
        EXPECT_NE(loser_of_point[first], loser_of_point[first - 1]) << name << " turn " << turn;
      }
      turn_servers.insert(server_of_point[first]);
    }
    EXPECT_EQ(turn_servers.size(), 4u) << name << ": the four turns' servers";
  }
}

// The default feed is untouched by the serve: the same seed plays the same match with `start`
// given as its default.
TEST(RacketSports, FeedIsTheDefaultStart) {
  auto a = make("table_tennis", "1v1", 9), b = make("table_tennis", "1v1", 9, {{"start", "feed"}});
  EXPECT_EQ(play(*a, 300, 0.05f), play(*b, 300, 0.05f));
}

}  // namespace
}  // namespace olympics::sports::racket
