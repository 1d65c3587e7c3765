// Whole javelin matches in process, the javelin placed and launched by hand: a tip-first landing
// in the sector is measured from the arc, a flat one and one outside the sector are fouls, an
// athlete on the arc fouls; the fingers hold the javelin at the cord and opening them lets it
// go; a competition ranks its athletes; and the air turns a thrown javelin tip first.
#include "javelin/javelin_match.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../athletics/field_event_session.h"
#include "javelin/javelin_aero.h"
#include "javelin/javelin_flight.h"
#include "javelin/javelin_sport.h"

namespace olympics::sports::javelin {
namespace {

using Session = athletics::FieldEventSession<JavelinMatch, JavelinSport>;

const nlohmann::json kStanding = {{"rules", "official"}, {"run_up", 2.0}, {"attempts", 1}};

// The javelin out of the hand, its tip at `tip` pointing `pitch_down_deg` below the horizontal
// (along +x, turned `yaw_deg` about z), moving at `speed` along its axis.
void launch(Javelin& j, const Eigen::Vector3d& tip, double pitch_down_deg, double speed,
            double yaw_deg = 0) {
  j.release();
  const Eigen::Quaterniond q =
      Eigen::AngleAxisd(yaw_deg * M_PI / 180, Eigen::Vector3d::UnitZ()) *
      Eigen::AngleAxisd(pitch_down_deg * M_PI / 180, Eigen::Vector3d::UnitY());
  const Eigen::Vector3d axis = q * Eigen::Vector3d::UnitX();
  j.place(tip - j.spec().tip_to_grip * axis, q);
  j.set_motion(speed * axis, Eigen::Vector3d::Zero());
}

nlohmann::json decision(Session& r, int ticks) {
  for (int i = 0; i < ticks && !r.match->outcome().match_over; ++i) {
    r.step();
    for (const auto& e : r.match->outcome().info["events"])
      if (e["call"] == "mark" || e["call"] == "foul") return e;
  }
  return nullptr;
}

TEST(JavelinMatch, ATipFirstLandingInTheSectorIsMeasuredFromTheArc) {
  Session r("javelin", "solo", kStanding);
  // The tip 1 cm above (44, 0), 45 degrees down: 50 m from the arc's centre (-6, 0), 42 m from
  // the arc.
  launch(r.match->javelin(0), {44.0, 0.0, 0.01}, 45, 1.0);
  const auto e = decision(r, 10);
  ASSERT_FALSE(e.is_null());
  ASSERT_EQ(e["call"], "mark") << e.dump();
  EXPECT_NEAR(e["mark"].get<double>(), 42.00, 0.02);
  EXPECT_DOUBLE_EQ(r.match->series(0).best(), e["mark"].get<double>());
  EXPECT_TRUE(r.match->outcome().match_over);
  EXPECT_EQ(r.match->outcome().reason, "series_complete");
}

TEST(JavelinMatch, AFlatLandingIsInvalid) {
  Session r("javelin", "solo", kStanding);
  launch(r.match->javelin(0), {44.0, 0.0, 0.05}, 0, 0.0);  // level: it falls flat
  const auto e = decision(r, 10);
  ASSERT_FALSE(e.is_null());
  EXPECT_EQ(e["call"], "foul");
  EXPECT_EQ(e["reason"], "flat");
  EXPECT_EQ(r.match->series(0).best(), 0.0);
}

TEST(JavelinMatch, ATailFirstLandingIsInvalid) {
  Session r("javelin", "solo", kStanding);
  launch(r.match->javelin(0), {44.0, 0.0, 1.5}, -40, 0.0);  // tip up: the tail lands first
  const auto e = decision(r, 30);
  ASSERT_FALSE(e.is_null());
  EXPECT_EQ(e["reason"], "flat");
}

TEST(JavelinMatch, ATipFirstLandingOutsideTheSectorIsInvalid) {
  Session r("javelin", "solo", kStanding);
  // (30, 10): atan(10 / 36) = 15.5 degrees off the axis, outside the 14.48 of half the sector.
  launch(r.match->javelin(0), {30.0, 10.0, 0.01}, 45, 1.0);
  const auto e = decision(r, 10);
  ASSERT_FALSE(e.is_null());
  EXPECT_EQ(e["reason"], "sector");
}

TEST(JavelinMatch, TouchingTheGroundBeyondTheArcBeforeTheLandingIsAFoul) {
  Session r("javelin", "solo", kStanding);
  r.match->athlete(0).reset({{2.3, 0, 0}, 0});  // standing on the arc, javelin in the air
  launch(r.match->javelin(0), {30.0, 0.0, 20.0}, 20, 0.0);
  const auto e = decision(r, 5);
  ASSERT_FALSE(e.is_null());
  EXPECT_EQ(e["reason"], "arc");
}

TEST(JavelinMatch, StandingBehindTheArcHoldingTheJavelinIsNoFoul) {
  Session r("javelin", "solo", kStanding);
  EXPECT_TRUE(decision(r, 12).is_null()) << "within present_s nothing is decided";
  EXPECT_TRUE(r.match->javelin(0).held());
}

// The right hand's finger links closed by `curl` rad about their x hinges (the thumb too).
std::vector<float> fingers_closed(const JavelinMatch& m, const core::Humanoid& h, double curl) {
  std::vector<float> a(m.action_size(), 0.0f);
  for (int b = 1; b < h.body_count(); ++b) {
    const std::string& name = h.spec().bodies[b].name;
    const bool right_finger =
        name.rfind("R_", 0) == 0 &&
        (name.find("Index") != std::string::npos || name.find("Middle") != std::string::npos ||
         name.find("Ring") != std::string::npos || name.find("Pinky") != std::string::npos);
    if (right_finger) a[3 * (b - 1)] = static_cast<float>(curl / M_PI);  // action scale pi
  }
  return a;
}

TEST(JavelinGrip, ClosedFingersHoldTheJavelinAtTheCordAndOpeningThemLetsItGo) {
  Session r("javelin", "solo", {{"rules", "official"}, {"run_up", 2.0}, {"attempt_s", 20}});
  JavelinMatch& m = *r.match;
  const std::vector<float> closed = fingers_closed(m, m.athlete(0), 0.4);
  std::vector<std::span<const float>> actions = {closed};
  for (int i = 0; i < 30; ++i) m.step(actions);  // 1 s: past present_s
  ASSERT_TRUE(m.javelin(0).held()) << "the closed fingers hold it";
  ThrowingHand hand(m.athlete(0));
  EXPECT_GT(hand.finger_flexion(m.athlete(0)), m.rules().grip_closed);
  EXPECT_LT((m.javelin(0).grip_point() - hand.cord_point(m.athlete(0))).norm(), 0.01)
      << "held at the cord";
  nlohmann::json release;
  for (int i = 0; i < 15 && release.is_null(); ++i) {
    r.step();  // zero targets: the fingers straighten
    for (const auto& e : m.outcome().info["events"])
      if (e["call"] == "release") release = e;
  }
  ASSERT_FALSE(release.is_null()) << "open fingers let go";
  EXPECT_FALSE(m.javelin(0).held());
}

TEST(JavelinGrip, OpenFingersDropTheJavelinOncePresentationEnds) {
  Session r("javelin", "solo", kStanding);
  const auto e = r.wait_for("release", 20);
  ASSERT_FALSE(e.is_null());
  EXPECT_NEAR(e["t"].get<double>(), r.match->rules().present_s, 0.01);
}

TEST(JavelinCompetition, ThreeAthletesAreRankedByTheirMarks) {
  Session r("javelin", "competition_3", kStanding);
  JavelinMatch& m = *r.match;
  // Each over its own arc (lanes 60 m apart): 42 m, flat, 30 m.
  launch(m.javelin(0), {44.0, m.lane_y(0), 0.01}, 45, 1.0);
  launch(m.javelin(1), {44.0, m.lane_y(1), 0.05}, 0, 0.0);
  launch(m.javelin(2), {32.0, m.lane_y(2), 0.01}, 45, 1.0);
  for (int i = 0; i < 10 && !m.outcome().match_over; ++i) r.step();
  ASSERT_TRUE(m.outcome().match_over);
  EXPECT_EQ(m.outcome().reason, "series_complete");
  EXPECT_EQ(m.outcome().info["places"], nlohmann::json({1, 3, 2}));
  EXPECT_EQ(m.outcome().winner_team, 0);
  EXPECT_NEAR(m.outcome().scores[0], 42.0, 0.02);
  EXPECT_NEAR(m.outcome().scores[2], 30.0, 0.02);
}

TEST(JavelinCompetition, EqualMarksShareThePlace) {
  Session r("javelin", "competition_2", kStanding);
  JavelinMatch& m = *r.match;
  for (int s = 0; s < 2; ++s) launch(m.javelin(s), {44.0, m.lane_y(s), 0.05}, 0, 0.0);  // flat
  for (int i = 0; i < 10 && !m.outcome().match_over; ++i) r.step();
  ASSERT_TRUE(m.outcome().match_over);
  EXPECT_EQ(m.outcome().info["places"], nlohmann::json({1, 1}));
  EXPECT_EQ(m.outcome().winner_team, -1);
}

TEST(JavelinAero, TheCentreOfPressureLiesBehindTheCentreOfMass) {
  const JavelinSpec j = official_javelin();
  // Flying along +x at 25 m/s, the tip 10 degrees above the path.
  const Eigen::Vector3d axis(std::cos(0.1745), 0, std::sin(0.1745));
  const AeroLoad load = crossflow_load(j, axis, {25, 0, 0}, Eigen::Vector3d::Zero());
  EXPECT_LT(load.force.x(), 0) << "drag";
  EXPECT_GT(load.force.z(), 0) << "lift";
  // A nose-down moment: about +y (x towards -z is a positive rotation about y... tip down).
  const Eigen::Vector3d tip_turn = load.torque.cross(axis);
  EXPECT_LT(tip_turn.z(), 0) << "the torque turns the tip down";
  // Aligned with the flow: skin friction only, no moment.
  const AeroLoad aligned = crossflow_load(j, Eigen::Vector3d::UnitX(), {25, 0, 0}, {0, 0, 0});
  EXPECT_NEAR(aligned.torque.norm(), 0.0, 1e-12);
  EXPECT_NEAR(aligned.force.z(), 0.0, 1e-12);
  EXPECT_LT(aligned.force.x(), 0);
}

}  // namespace
}  // namespace olympics::sports::javelin

namespace olympics::sports::javelin {
namespace {

// A good throw (25 m/s at 35 degrees, the javelin along its path): with the air, the moment of
// the centre of pressure behind the centre of mass turns the tip down with the path and it lands
// tip first; in a vacuum (the seed's simulator) it keeps its 35 degrees up and lands tail first.
TEST(JavelinFlight, TheAirTurnsAThrownJavelinTipFirstAVacuumDoesNot) {
  const JavelinRelease good;  // 25 m/s, 35 degrees, attitude 35
  const JavelinLanding air = fly(official_javelin(), true, good);
  const JavelinLanding vacuum = fly(official_javelin(), false, good);
  ASSERT_TRUE(air.landed);
  ASSERT_TRUE(vacuum.landed);
  EXPECT_TRUE(air.tip_first);
  EXPECT_FALSE(vacuum.tip_first);
  // Both fly some 60 m (the crossflow's lift about makes up for its drag at these angles).
  EXPECT_GT(vacuum.first_touch.x(), 55.0);
  EXPECT_GT(air.first_touch.x(), 55.0);
}

}  // namespace
}  // namespace olympics::sports::javelin
