// Whole high-jump matches in process with scripted set-ups: the crossbar rests on its supports
// and falls when knocked (a failure); a body that goes over cleanly and lands on the soft mat
// clears; the mat gives under a landing as the ground does not.
#include "high_jump/high_jump_match.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "../athletics/field_event_session.h"
#include "high_jump/high_jump_sport.h"

namespace olympics::sports::high_jump {
namespace {

using Session = athletics::FieldEventSession<HighJumpMatch, HighJumpSport>;
using athletics::give_velocity;

Session start(const std::string& mode, const nlohmann::json& options) {
  return Session("high_jump", mode, options);
}

const nlohmann::json kOfficial = {{"rules", "official"}, {"bar_height", 0.5}};

TEST(HighJumpMatch, TheBarRestsOnItsSupportsUntouched) {
  Session r = start("solo", kOfficial);
  const Eigen::Vector3d rest = r.match->bar(0).position();
  for (int i = 0; i < 60; ++i) r.step();  // 2 s, the athlete standing 20 m away
  EXPECT_TRUE(r.match->bar(0).in_place());
  EXPECT_LT((r.match->bar(0).position() - rest).norm(), 0.005);
}

TEST(HighJumpMatch, ABarKnockedFallsAndTheAttemptFails) {
  for (const auto& options : {kOfficial, nlohmann::json{{"bar_height", 0.5}}}) {
    Session r = start("solo", options);
    dBodySetLinearVel(r.match->bar(0).body(), 1.0, 0, 0);  // knocked toward the mat
    const auto e = r.wait_for("failure", 30);
    ASSERT_FALSE(e.is_null()) << options;
    EXPECT_EQ(e["reason"], "bar_dislodged");
    EXPECT_DOUBLE_EQ(e["height"].get<double>(), 0.5);
  }
}

// The installation alone: the official bar stays on its supports for seconds untouched, and a
// knock sends it off them down to the ground.
TEST(Crossbar, RestsUntouchedAndFallsWhenKnocked) {
  core::PhysicsWorld world;
  HighJumpRules rules;
  rules.bar_length = 4.0, rules.bar_radius = 0.015, rules.bar_mass = 2.0;
  rules.support_depth = 0.04, rules.support_length = 0.06;
  Crossbar bar(world, rules, 0.0, 0.0, 1.2);
  EXPECT_NEAR(bar.end(-1).y(), -2.0, 1e-9);
  EXPECT_NEAR(bar.end(1).z(), 1.2 - 0.015, 1e-9) << "the bar's top at the height";
  const double dt = 1.0 / 120;
  for (int i = 0; i < 360; ++i) world.step(dt);
  EXPECT_TRUE(bar.in_place());
  EXPECT_NEAR(bar.position().z(), 1.2 - 0.015, 0.003);
  dBodySetLinearVel(bar.body(), 0.5, 0, 0);  // a light knock across the supports
  for (int i = 0; i < 120; ++i) world.step(dt);
  EXPECT_FALSE(bar.in_place());
  EXPECT_LT(bar.position().z(), 0.05) << "down on the ground";
  bar.set(1.3);  // put back, a height up
  EXPECT_TRUE(bar.in_place());
  EXPECT_NEAR(bar.position().z(), 1.3 - 0.015, 1e-9);
}

// A bar pushed along at its own height (on a jumper's head, as the scripted tucked jump did
// with the seed's 8 kg bar: 1.4-1.9 m before its "clearance") is off its supports: dislodged,
// though neither end has dropped. Before, only the ends' drop counted.
TEST(Crossbar, ABarCarriedOffItsSupportsAtItsHeightIsDislodged) {
  core::PhysicsWorld world;
  for (const bool official : {false, true}) {
    HighJumpRules rules;
    if (official) {
      rules.bar_length = 4.0, rules.bar_radius = 0.015, rules.bar_mass = 2.0;
      rules.support_depth = 0.04, rules.support_length = 0.06;
    }
    Crossbar bar(world, rules, 0.0, 0.0, 0.5);
    const Eigen::Vector3d rest = bar.position();
    dBodySetPosition(bar.body(), rest.x() + 0.01, rest.y(), rest.z() + 0.005);
    EXPECT_TRUE(bar.in_place()) << "a centimetre across and lifted: still on its supports";
    dBodySetPosition(bar.body(), rest.x() + 0.3, rest.y(), rest.z() + 0.05);
    EXPECT_FALSE(bar.in_place()) << "carried 0.3 m across, above its height";
    dBodySetPosition(bar.body(), rest.x() - 0.06, rest.y(), rest.z());
    EXPECT_FALSE(bar.in_place()) << "pushed back 6 cm, off the supports' far edge";
  }
}

TEST(HighJumpMatch, ABodyOverTheBarCleanlyIsAClearance) {
  Session r = start("solo", kOfficial);
  core::Humanoid& h = r.match->athlete(0);
  const double bar_y = r.match->rules().bar_y;
  // Upright, its feet well above the 0.5 m bar, moving over it toward the mat.
  h.reset({{19.5, bar_y, 2.1}, 0});
  give_velocity(h, {3.0, 0, 0});
  const auto e = r.wait_for("cleared", 120);
  ASSERT_FALSE(e.is_null()) << "no clearance";
  EXPECT_DOUBLE_EQ(e["height"].get<double>(), 0.5);
  EXPECT_TRUE(r.match->bar(0).in_place());
  EXPECT_DOUBLE_EQ(r.match->series(0).best(), 0.5);
  EXPECT_DOUBLE_EQ(r.match->series(0).bar_height(), 0.55) << "the bar goes up by the raise";
  EXPECT_DOUBLE_EQ(r.match->bar(0).height(), 0.55);
}

// A competition of two, stepped by hand: slot 0 is launched over its bar, slot 1 knocks its bar
// off at once. The tries go round (slot 1's second try waits for slot 0's first to be decided)
// and the bar rises only when slot 1 is out, though slot 0 cleared long before.
bool step_until(Session& r, const std::function<bool()>& done, int ticks) {
  for (int i = 0; i < ticks && !done(); ++i) r.step();
  return done();
}

void launch_over_the_bar(Session& r, int slot) {
  core::Humanoid& h = r.match->athlete(slot);
  h.reset({{19.5, r.match->rules().bar_y + r.match->lane_y(slot), 2.1}, 0});
  give_velocity(h, {3.0, 0, 0});
}

// Whether the last tick called an attempt of the slot (cleared or failure, the jump-off's too).
bool attempt_called(const Session& r, int slot) {
  for (const auto& e : r.match->outcome().info["events"])
    if (e.value("slot", -1) == slot && (e["call"] == "cleared" || e["call"] == "failure"))
      return true;
  return false;
}

// Knocks the slot's bar off once its next attempt is on, and steps until the attempt is called
// (the next try may start in the same tick).
bool knock_the_bar(Session& r, int slot) {
  if (!step_until(
          r, [&] { return r.match->in_attempt(slot); }, 300))
    return false;
  dBodySetLinearVel(r.match->bar(slot).body(), 1.0, 0, 0);
  for (int i = 0; i < 60; ++i) {
    r.step();
    if (attempt_called(r, slot)) return true;
  }
  return false;
}

TEST(HighJumpMatch, TheBarRisesOnlyWhenBothAthletesHaveHadTheirTriesAtIt) {
  Session r = start("competition_2", {{"rules", "official"}, {"bar_height", 0.5}, {"heights", 3}});
  launch_over_the_bar(r, 0);
  ASSERT_TRUE(knock_the_bar(r, 1));
  EXPECT_TRUE(r.match->in_attempt(0));
  EXPECT_FALSE(r.match->in_attempt(1)) << "slot 1's second try waits for slot 0's first";
  ASSERT_TRUE(step_until(
      r, [&] { return !r.match->in_attempt(0); }, 150))
      << "no clearance";
  EXPECT_DOUBLE_EQ(r.match->series(0).best(), 0.5);
  EXPECT_DOUBLE_EQ(r.match->rounds().bar_height(), 0.5) << "slot 1 is still in at 0.5";
  EXPECT_DOUBLE_EQ(r.match->bar(0).height(), 0.5);
  ASSERT_TRUE(knock_the_bar(r, 1));  // its second try
  EXPECT_FALSE(r.match->in_attempt(0)) << "slot 0 waits, unjudged";
  ASSERT_TRUE(knock_the_bar(r, 1));  // its third: out
  EXPECT_TRUE(r.match->series(1).done());
  EXPECT_DOUBLE_EQ(r.match->rounds().bar_height(), 0.55) << "slot 1 out: the bar goes up";
  EXPECT_TRUE(r.match->in_attempt(0));
  EXPECT_DOUBLE_EQ(r.match->bar(0).height(), 0.55);
  for (int t = 0; t < 3; ++t) ASSERT_TRUE(knock_the_bar(r, 0));
  r.step();
  ASSERT_TRUE(r.match->outcome().match_over);
  EXPECT_EQ(r.match->outcome().info["places"], (std::vector<int>{1, 2}));
}

// Both clear the one height at the first try: tied after the countback, they jump off at the
// next height; slot 0 clears it, slot 1 fails, and the places are distinct.
TEST(HighJumpMatch, ATieForFirstIsDecidedByAJumpOff) {
  Session r = start("competition_2", {{"rules", "official"}, {"bar_height", 0.5}, {"heights", 1}});
  launch_over_the_bar(r, 0);
  launch_over_the_bar(r, 1);
  ASSERT_TRUE(step_until(
      r, [&] { return r.match->rounds().in_jump_off(); }, 150));
  EXPECT_EQ(r.match->series(0).best(), r.match->series(1).best());
  EXPECT_DOUBLE_EQ(r.match->rounds().bar_height(), 0.55) << "one try at the next height";
  ASSERT_TRUE(step_until(
      r, [&] { return r.match->in_attempt(0) && r.match->in_attempt(1); }, 5));
  launch_over_the_bar(r, 0);
  ASSERT_TRUE(knock_the_bar(r, 1));
  ASSERT_TRUE(step_until(
      r, [&] { return r.match->outcome().match_over; }, 150));
  EXPECT_EQ(r.match->outcome().info["places"], (std::vector<int>{1, 2}));
  EXPECT_DOUBLE_EQ(r.match->series(0).best(), 0.5) << "the jump-off places, the best stays";
}

TEST(HighJumpMatch, PaperClearsOnceEveryBodyIsPastTheBar) {
  Session r = start("solo", {{"bar_height", 0.5}});
  core::Humanoid& h = r.match->athlete(0);
  h.reset({{19.5, r.match->rules().bar_y, 2.1}, 0});
  give_velocity(h, {3.0, 0, 0});
  const auto e = r.wait_for("cleared", 60);
  ASSERT_FALSE(e.is_null());
  EXPECT_TRUE(r.match->outcome().match_over) << "one height, one try: the seed's episode";
}

TEST(HighJumpMatch, RunningUnderTheBarFails) {
  Session r = start("solo", {{"rules", "official"}, {"bar_height", 2.0}});
  core::Humanoid& h = r.match->athlete(0);
  h.reset({{19.5, r.match->rules().bar_y, 1.2}, 0});  // the head below the 2 m bar
  give_velocity(h, {3.0, 0, 0});
  const auto e = r.wait_for("failure", 60);
  ASSERT_FALSE(e.is_null());
  EXPECT_EQ(e["reason"], "touched_beyond");
}

TEST(HighJumpMatch, StandingInTheRunUpFanIsNoFailureLeavingItIs) {
  // The 25 m fan round the bar's centre (20, bar_y): an athlete placed 24.5 m out (inside) goes
  // on until its zero action lets it fall; one placed 25.5 m out fails at once for leaving it.
  const double bar_x = 20.0;
  for (const double out : {24.5, 25.5}) {
    Session r = start("solo", kOfficial);
    ASSERT_EQ(r.match->rules().bar_x, bar_x);
    core::Humanoid& h = r.match->athlete(0);
    const double a = 0.75 * M_PI;  // ahead-left of the bar, on the approach side
    h.reset({{bar_x + out * std::cos(a), r.match->rules().bar_y + out * std::sin(a), 0.0}, 0});
    const auto e = r.wait_for("failure", 90);
    ASSERT_FALSE(e.is_null());
    if (out < 25) {
      EXPECT_EQ(e["reason"], "fell") << "in the fan: judged by the other rules only";
      EXPECT_GT(e["t"].get<double>(), 0.3);
    } else {
      EXPECT_EQ(e["reason"], "left_area");
      EXPECT_LT(e["t"].get<double>(), 0.1) << "at once";
    }
  }
}

TEST(HighJumpMatch, TheSoftMatGivesUnderALanding) {
  Session r = start("solo", kOfficial);
  core::Humanoid& h = r.match->athlete(0);
  const double bar_y = r.match->rules().bar_y;
  h.reset({{22.0, bar_y, kMatHeight + 1.5}, 0});  // dropped flat-footed onto the mat
  double lowest = 1e9;                            // the lowest point of any of its geoms
  for (int i = 0; i < 45; ++i) {
    r.step();
    for (int b = 0; b < h.body_count(); ++b)
      for (dGeomID g = dBodyGetFirstGeom(h.ode_body(b)); g; g = dBodyGetNextGeom(g)) {
        dReal aabb[6];
        dGeomGetAABB(g, aabb);
        lowest = std::min(lowest, static_cast<double>(aabb[4]));
      }
  }
  EXPECT_LT(lowest, kMatHeight - 0.03) << "the feet sank into the foam";
  EXPECT_GT(lowest, 0.2) << "and the mat held them";
}

}  // namespace
}  // namespace olympics::sports::high_jump
