// Whole golf matches in process, the ball moved by hand where a test needs a shot: a ball sent
// into the club head is a stroke (and the club's contact the seed's C_b), a ball that comes to
// rest has the athlete addressed beside it, a ball rolled into the hole is holed; a competition
// of three ranks the fewest strokes first; the paper mode ends as the seed does.
#include "golf/golf_match.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../athletics/field_event_session.h"
#include "golf/golf_sport.h"

namespace olympics::sports::golf {
namespace {

using Session = athletics::FieldEventSession<GolfMatch, GolfSport>;

// Sends the ball at 3 m/s into the face of the athlete's club head from 8 cm in front of it.
void strike(GolfMatch& m, int slot) {
  const core::BodyState hand = m.athlete(slot).body_state(m.hand_body());
  const Eigen::Vector3d face = hand.orientation * Eigen::Vector3d::UnitX();
  m.ball(slot).set_state(m.club_head(slot) + 0.08 * face, -3.0 * face);
}

// Rolls the ball slowly into the athlete's hole from 0.2 m short of it.
void roll_in(GolfMatch& m, int slot) {
  const Eigen::Vector3d hole = m.target(slot);
  const Eigen::Vector3d v(0.5, 0, 0);
  const double r = m.ball(slot).spec().radius;
  m.ball(slot).set_state(hole + Eigen::Vector3d(-0.2, 0, r), v, m.ball(slot).rolling_spin(v));
}

// This tick's calls (info["events"] holds one tick's) added to `log`.
void keep_events(const GolfMatch& m, nlohmann::json& log) {
  for (const auto& e : m.outcome().info["events"]) log.push_back(e);
}

int count_calls(const nlohmann::json& log, const std::string& call, int slot) {
  int n = 0;
  for (const auto& e : log) n += e["call"] == call && e["slot"] == slot;
  return n;
}

TEST(GolfMatch, AClubContactIsAStrokeAndAHoledBallEndsTheHole) {
  Session s("golf", "solo", {{"rules", "official"}});
  GolfMatch& m = *s.match;
  EXPECT_EQ(m.rules().club.name, "putter");
  strike(m, 0);
  const nlohmann::json stroke = s.wait_for("stroke", 5);
  ASSERT_FALSE(stroke.is_null()) << "the club's contact with the ball is a stroke";
  EXPECT_EQ(stroke["stroke"], 1);
  EXPECT_EQ(m.hole_referee(0).strokes(), 1);
  EXPECT_EQ(m.outcome().terms[0][0], 1.0f) << "r_c is 1 once the club has struck";
  const nlohmann::json rest = s.wait_for("at_rest", 600);
  ASSERT_FALSE(rest.is_null());
  EXPECT_EQ(m.hole_referee(0).strokes(), 1) << "the ball's bounces are no strokes";
  // Addressed again: the athlete stands beside the ball, facing the hole.
  const Eigen::Vector3d root = m.athlete(0).body_state(0).position;
  EXPECT_NEAR((root - m.ball(0).position()).head<2>().norm(), m.rules().address_side, 0.05);
  roll_in(m, 0);
  const nlohmann::json holed = s.wait_for("holed", 120);
  ASSERT_FALSE(holed.is_null());
  EXPECT_EQ(holed["strokes"], 1);
  EXPECT_TRUE(m.outcome().match_over);
  EXPECT_EQ(m.outcome().reason, "holes_complete");
  EXPECT_EQ(m.outcome().scores[0], 1.0f);
  EXPECT_EQ(m.outcome().info["places"], nlohmann::json::array({1}));
}

TEST(GolfMatch, ACompetitionRanksTheFewestStrokesFirst) {
  Session s("golf", "competition_3", {{"rules", "official"}, {"hole_s", 5}});
  GolfMatch& m = *s.match;
  strike(m, 0);
  strike(m, 1);
  for (int i = 0; i < 20; ++i) s.step();
  strike(m, 1);  // a second stroke, 0.67 s after the first
  for (int i = 0; i < 3; ++i) s.step();
  EXPECT_EQ(m.hole_referee(0).strokes(), 1);
  EXPECT_EQ(m.hole_referee(1).strokes(), 2);
  roll_in(m, 0);
  roll_in(m, 1);
  nlohmann::json log = nlohmann::json::array();
  for (int i = 0; i < 30 * 6 && !m.outcome().match_over; ++i) {
    s.step();
    keep_events(m, log);
  }
  ASSERT_TRUE(m.outcome().match_over);
  EXPECT_EQ(count_calls(log, "holed", 0), 1);
  EXPECT_EQ(count_calls(log, "holed", 1), 1);
  EXPECT_EQ(count_calls(log, "picked_up", 2), 1) << "slot 2 never struck: the time ran out";
  EXPECT_EQ(m.outcome().info["places"], nlohmann::json::array({1, 2, 3}));
  EXPECT_EQ(m.outcome().scores, (std::vector<float>{1, 2, 6}));
  EXPECT_EQ(m.outcome().winner_team, 0);
}

TEST(GolfMatch, EqualScoresShareAPlace) {
  Session s("golf", "competition_2", {{"rules", "official"}, {"hole_s", 5}});
  for (int i = 0; i < 30 * 6 && !s.match->outcome().match_over; ++i) s.step();
  ASSERT_TRUE(s.match->outcome().match_over);
  EXPECT_EQ(s.match->outcome().info["places"], nlohmann::json::array({1, 1}));
  EXPECT_EQ(s.match->outcome().winner_team, -1);
}

TEST(GolfMatch, PaperIsTheSeedsShot) {
  Session s("golf", "solo", {});
  GolfMatch& m = *s.match;
  EXPECT_EQ(m.rules().club.name, "seed_club");
  EXPECT_EQ(m.hole(0), nullptr) << "the seed has no hole";
  EXPECT_NEAR(m.target(0).x(), 0.0, 1e-12);
  EXPECT_LE(m.target(0).y(), 0.0);
  EXPECT_GE(m.target(0).y(), -20.0);
  const nlohmann::json end = s.wait_for("shot_end", 90);
  ASSERT_FALSE(end.is_null()) << "standing still, the seed ends the shot within 61 ticks";
  EXPECT_FALSE(end["hit"].get<bool>());
  EXPECT_FALSE(end["success"].get<bool>());
  EXPECT_TRUE(m.outcome().match_over);
}

TEST(GolfMatch, ASlopingGreenBreaksThePuttAndAFlatOneDoesNot) {
  // A 1.2 m/s roll towards the hole 2 m away (it stops about 1.3 m out) on a green falling 3%
  // to the left: it ends left of the line, as far as the ball on its own (golf_green_test) says.
  double end_y[2];
  for (int sloped = 0; sloped < 2; ++sloped) {
    Session s("golf", "solo",
              {{"rules", "official"}, {"green_slope", sloped ? 3.0 : 0.0}, {"green_fall", 90}});
    GolfMatch& m = *s.match;
    const Eigen::Vector3d v(1.2, 0, 0);
    m.ball(0).set_state(m.ball(0).position(), v, m.ball(0).rolling_spin(v));
    for (int i = 0; i < 180; ++i) s.step();  // 6 s: it stops in about 3
    EXPECT_LT(m.ball(0).velocity().norm(), 0.01);
    end_y[sloped] = m.ball(0).position().y();
  }
  EXPECT_NEAR(end_y[0], 0.0, 1e-3) << "flat: straight";
  EXPECT_GT(end_y[1], 0.05) << "3% falling left: it breaks left";
  std::printf("a 1.2 m/s roll on a green falling 3%% to the left ends %.3f m left\n", end_y[1]);
}

TEST(GolfMatch, WithAddressWalkTheAthleteIsPlacedOnlyForTheFirstStroke) {
  // The same stroke, placed or walking: at rest, "placed" puts the athlete beside the ball;
  // "walk" leaves it where it stood (a policy walks it there).
  for (const std::string address : {"placed", "walk"}) {
    Session s("golf", "solo", {{"rules", "official"}, {"address", address}});
    GolfMatch& m = *s.match;
    const Eigen::Vector3d first = m.athlete(0).body_state(0).position;
    EXPECT_NEAR((first - m.ball(0).position()).head<2>().norm(),
                std::hypot(m.rules().address_side, m.rules().address_ahead), 0.05)
        << address << ": placed for the first stroke";
    strike(m, 0);
    Eigen::Vector3d before_rest = first;
    nlohmann::json rest;
    for (int i = 0; i < 600 && rest.is_null(); ++i) {
      before_rest = m.athlete(0).body_state(0).position;
      s.step();
      for (const auto& e : m.outcome().info["events"])
        if (e["call"] == "at_rest") rest = e;
    }
    ASSERT_FALSE(rest.is_null()) << address;
    const Eigen::Vector3d after = m.athlete(0).body_state(0).position;
    const double to_ball = (after - m.ball(0).position()).head<2>().norm();
    if (address == "placed") {
      EXPECT_NEAR(to_ball, std::hypot(m.rules().address_side, m.rules().address_ahead), 0.05);
    } else {
      EXPECT_LT((after - before_rest).norm(), 0.05) << "not moved by the referee";
      EXPECT_GT(to_ball, 0.6) << "the ball rolled away from it";
    }
  }
}

}  // namespace
}  // namespace olympics::sports::golf
