// Whole long-jump matches in process, with the athlete placed by hand: a toe past the foul line
// on the ground is a foul; a body that comes down in the sand is measured to the nearest break;
// a competition ranks its athletes.
#include "long_jump/long_jump_match.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "../athletics/field_event_session.h"
#include "athletics/athlete_probe.h"
#include "long_jump/long_jump_sport.h"

namespace olympics::sports::long_jump {
namespace {

using Session = athletics::FieldEventSession<LongJumpMatch, LongJumpSport>;
using athletics::give_velocity;

Session start(const std::string& mode, const nlohmann::json& options) {
  return Session("long_jump", mode, options);
}

TEST(LongJumpMatch, AToePastTheFoulLineOnTheGroundIsAFoul) {
  Session r = start("solo", {{"rules", "official"}});
  core::Humanoid& h = r.match->athlete(0);
  h.reset({{19.90, 0, 0}, 0});  // standing on the board, facing the pit
  ASSERT_GT(athletics::foremost_x(h), 20.0) << "the set-up: the toes reach past the line";
  const auto e = r.wait_for("foul", 3);
  ASSERT_FALSE(e.is_null());
  EXPECT_EQ(e["reason"], "past_the_line");
  EXPECT_EQ(r.match->series(0).fouls(), 1);
}

TEST(LongJumpMatch, StandingBehindTheLineIsNoFoul) {
  Session r = start("solo", {{"rules", "official"}});
  core::Humanoid& h = r.match->athlete(0);
  h.reset({{19.70, 0, 0}, 0});
  ASSERT_LT(athletics::foremost_x(h), 20.0);
  EXPECT_TRUE(r.wait_for("foul", 10).is_null());
}

TEST(LongJumpMatch, TheMarkIsTheNearestBreakInTheSand) {
  Session r = start("solo", {{"rules", "official"}, {"attempts", 1}});
  core::Humanoid& h = r.match->athlete(0);
  // Dropped into the pit moving back toward the line: heels first, then it sits back.
  h.reset({{26.0, 0, 1.3}, 0});
  give_velocity(h, {-1.5, 0, -1.0});
  double nearest_point = 1e9;  // the rearmost point of the body while in the pit, for comparison
  nlohmann::json mark;
  for (int i = 0; i < 120 && mark.is_null(); ++i) {
    r.step();
    const double rear = [&] {
      double x = 1e9;
      for (int b = 0; b < h.body_count(); ++b)
        for (dGeomID g = dBodyGetFirstGeom(h.ode_body(b)); g; g = dBodyGetNextGeom(g)) {
          dReal aabb[6];
          dGeomGetAABB(g, aabb);
          if (aabb[4] < 0.05) x = std::min(x, static_cast<double>(aabb[0]));  // at the sand
        }
      return x;
    }();
    nearest_point = std::min(nearest_point, rear);
    for (const auto& e : r.match->outcome().info["events"])
      if (e["call"] == "mark") mark = e;
  }
  ASSERT_FALSE(mark.is_null()) << "the landing was measured";
  const double m = mark["mark"];
  EXPECT_LT(m, 26.0 - 20.0 - 0.3) << "it sat back: the nearest break is behind the feet";
  EXPECT_NEAR(m, nearest_point - 20.0, 0.1) << "the rearmost part that reached the sand";
  EXPECT_DOUBLE_EQ(r.match->series(0).best(), m);
  EXPECT_TRUE(r.match->outcome().match_over) << "one attempt in this series";
}

TEST(LongJumpMatch, PaperMeasuresTheMeanXOfTheBodiesAtTheLanding) {
  Session r = start("solo", {});
  core::Humanoid& h = r.match->athlete(0);
  h.reset({{24.0, 0, 1.2}, 0});
  give_velocity(h, {0.5, 0, 0});
  const auto e = r.wait_for("mark", 60);
  ASSERT_FALSE(e.is_null());
  EXPECT_NEAR(e["mark"].get<double>(), athletics::mean_body_position(h).x() - 20.0, 0.1);
  EXPECT_NEAR(r.match->outcome().terms[0][3], e["mark"].get<double>(), 1e-5) << "r_l";
}

TEST(LongJumpMatch, ACompetitionRanksItsAthletesWhenEverySeriesIsOver) {
  Session r = start("competition_3", {{"rules", "official"}, {"attempts", 1}});
  ASSERT_EQ(r.match->slot_count(), 3);
  for (int slot = 0; slot < 3; ++slot) {
    core::Humanoid& h = r.match->athlete(slot);
    const double x = std::vector<double>{24.0, 26.0, 19.9}[slot];  // the third fouls
    h.reset({{x, r.match->lane_y(slot), x > 20 ? 1.2 : 0.0}, 0});
  }
  for (int i = 0; i < 150 && !r.match->outcome().match_over; ++i) r.step();
  const TickOutcome& o = r.match->outcome();
  ASSERT_TRUE(o.match_over);
  EXPECT_EQ(o.reason, "series_complete");
  EXPECT_EQ(o.info["places"], (std::vector<int>{2, 1, 3}));
  EXPECT_EQ(o.winner_team, 1);
  EXPECT_GT(o.scores[1], o.scores[0]);
  EXPECT_EQ(o.scores[2], 0.0f);
}

}  // namespace
}  // namespace olympics::sports::long_jump
