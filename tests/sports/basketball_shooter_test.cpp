// The scripted free-throw shooter (clients/agent/scripted_basketball.h), played in process: it
// cradles the presented ball, swings it up to the rim's height, and makes free throws; and the
// free throw's rule that a fall after the release does not end the throw.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "ball_aim.h"
#include "basketball/basketball_match.h"
#include "registry.h"
#include "scripted_basketball.h"
#include "zero_play.h"

namespace olympics::sports::basketball {
namespace {

using Eigen::Vector3d;

// A seed the baseline makes (of seeds 1..100 it makes 73, among them 2-4, 7-12, 16, 17, 19-21, 23,
// 25 and 26, with its cradle settled alike on every seed and its trunk twisted towards the rim;
// with the cradle turned to the rim, 1, 7, 16, 18, 24, 25, 34, 55, 59, 60, 67, 77, 80, 85, 92 and
// 97; untrimmed, as before issue 30, 12, 16, 24, 25, 67, 77 and 92).
constexpr std::uint64_t kMadeSeed = 25;

struct Throw {
  std::string reason;
  float score = 0;
  double highest_m = 0;            // the ball's highest point
  double ball_from_palms_m = 1e9;  // at the swing's start: the ball from the palms' midpoint
  double ball_ahead_m = NAN;       // the same, towards the rim (horizontally)
  // The ball's speed on the first tick after the swing's start that it is clear of the palms (its
  // centre 0.2 m from their midpoint), as the bench measures the release; 0: never clear.
  double release_speed = 0;
  // Where the ball, released, first comes down through 13 cm above the rim's height (about where
  // it meets the rim): m to the left (+) or right (-) of the rim's centre, seen from the release
  // point; NaN if it never does. The rim's centre is over the court's origin.
  double side_at_rim_m = NAN;
  // There: m beyond (+) or short of (-) the rim's centre, along the line from the release.
  double long_at_rim_m = NAN;
  double release_elevation_deg = NAN;  // the ball's direction at the release, above the horizontal
  bool fell = false;                   // the shooter's root below 0.5 m at any tick
  Vector3d ball_at_swing = Vector3d::Zero(), ball_at_release = Vector3d::Zero();
  client::FreeThrowAim aim;
};

// The centre of a palm (the wrist body's box, HUMANOID-SMPLX.md: 5 cm out along the hand).
Vector3d palm_centre(const core::Humanoid& h, int wrist, double out) {
  const core::BodyState s = h.body_state(wrist);
  return s.position + s.orientation * Vector3d(0, out, 0);
}

// One free throw of seed `seed` shot by the scripted baseline.
Throw shoot(std::uint64_t seed, const nlohmann::json& settings = {},
            const client::FreeThrowShot& shot = {}) {
  auto m = sport_or_throw("basketball").create({"free_throw", seed, 0.0, settings});
  auto& b = dynamic_cast<BasketballMatch&>(*m);
  client::ScriptedBasketballPolicy shooter(shot);
  shooter.start({"basketball", "free_throw", 1.0 / 30,
                 client::ObservationLayout::from_blocks(m->layout().observation),
                 m->action_size()});
  std::vector<float> obs(m->obs_size()), act(m->action_size());
  Throw t;
  const core::Humanoid& h = std::as_const(b).scene().humanoid(0);
  auto palms = [&]() -> Vector3d {
    return 0.5 * (palm_centre(h, 17, 0.0523) + palm_centre(h, 36, -0.0537));
  };
  auto ball_from_palms = [&] { return (b.ball().position() - palms()).norm(); };
  const int swing_tick = static_cast<int>(shot.shot_s * 30);
  Vector3d towards_rim = Vector3d::UnitX();
  for (int tick = 0; tick < 6 * 30 && !m->outcome().match_over; ++tick) {
    if (tick == swing_tick) {
      t.ball_from_palms_m = ball_from_palms();
      const Vector3d ball = b.ball().position();
      t.ball_ahead_m = Vector3d(-ball.x(), -ball.y(), 0).normalized().dot(ball - palms());
      t.ball_at_swing = ball;
    }
    m->observe(0, obs);
    shooter.act(obs, act);
    m->step({std::span<const float>(act)});
    t.highest_m = std::max(t.highest_m, b.ball().position().z());
    const Vector3d ball = b.ball().position();
    if (tick >= swing_tick && t.release_speed == 0 && ball_from_palms() >= 0.2) {
      const Vector3d v = b.ball().velocity();
      t.release_speed = v.norm();
      t.ball_at_release = ball;
      t.release_elevation_deg = std::atan2(v.z(), v.head<2>().norm()) * 180 / M_PI;
      towards_rim = Vector3d(-ball.x(), -ball.y(), 0).normalized();
    } else if (t.release_speed > 0 && std::isnan(t.side_at_rim_m) && b.ball().velocity().z() < 0 &&
               ball.z() < 3.05 + 0.13) {
      t.side_at_rim_m = Vector3d::UnitZ().cross(towards_rim).dot(Vector3d(ball.x(), ball.y(), 0));
      t.long_at_rim_m = towards_rim.dot(Vector3d(ball.x(), ball.y(), 0));
    }
    if (h.body_state(0).position.z() < 0.5) t.fell = true;
  }
  t.reason = m->outcome().reason;
  t.score = m->outcome().scores[0];
  t.aim = shooter.aim();
  return t;
}

TEST(ScriptedFreeThrow, CradlesThePresentedBallAndSwingsItAboveTheRim) {
  int cradled = 0, above_rim = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const Throw t = shoot(seed);
    if (t.ball_from_palms_m < 0.15) ++cradled;  // the ball (r 0.12) lies between the palms
    if (t.highest_m > 3.05) ++above_rim;
  }
  // Measured: 10 of 10 still in the hands at the swing; 4 of 10 above the rim with the
  // FIBA-calibrated ball (restitution 0.795: it leaves the striking hands slower), 6 of 10 with
  // the livelier 0.88 of before issue 33.
  EXPECT_GE(cradled, 9);
  EXPECT_GE(above_rim, 3);
}

TEST(ScriptedFreeThrow, MakesAFreeThrow) {
  const Throw t = shoot(kMadeSeed);
  EXPECT_EQ(t.reason, "basket");
  EXPECT_EQ(t.score, 1.0f);
}

TEST(ScriptedFreeThrow, AimsByTheBallisticSolution) {
  // The aim asks for the launch speed whose path (gravity and drag) comes down through the
  // rim's centre from the release point (a check of the solver), and, what checks the frames
  // and the table, a line 1 m nearer for a carry 1 m shorter and a weaker swing.
  const Throw near = shoot(kMadeSeed, {{"free_throw_distance", 3.6}});
  const Throw usual = shoot(kMadeSeed);
  const client::FreeThrowShot shot;
  const double drag = shot.ball_drag, up = shot.launch_elevation;
  for (const Throw* t : {&near, &usual}) {
    ASSERT_GT(t->aim.launch_speed, 0);
    EXPECT_NEAR(client::carry_to_height(t->aim.launch_speed, up, t->aim.rise, drag), t->aim.carry,
                0.01);
  }
  EXPECT_NEAR(usual.aim.carry - near.aim.carry, 1.0, 0.1) << "the line is 1 m nearer";
  EXPECT_LT(near.aim.launch_speed, usual.aim.launch_speed - 0.5);
  EXPECT_LT(near.aim.elevation, usual.aim.elevation - 0.3) << "a weaker swing for the nearer rim";
}

TEST(ScriptedFreeThrow, MakesFreeThrowsFromNearerLinesWhereTheSearchedSwingCannot) {
  // Seeds 1..100 from 3.6 and 4.0 m (the line 1 and 0.6 m nearer). Measured: 61 of the 200 made
  // by the aimed swing (from 4.0 m with its release trimmed, 3.6 m untrimmed), 0 by the search's
  // swing (2.596 rad, untrimmed) kept whatever the line; with the cradle of before, turned to
  // the rim: 18 and 4 (16 aimed before issue 30; with the livelier ball of before issue 33: 8
  // and 1, untrimmed).
  client::FreeThrowShot kept;
  kept.fixed_elevation = 2.596;
  kept.trim_tick = 0;  // the search's swing as it was: untrimmed
  int aimed = 0, fixed = 0;
  for (double line : {3.6, 4.0})
    for (std::uint64_t seed = 1; seed <= 100; ++seed) {
      aimed += shoot(seed, {{"free_throw_distance", line}}).reason == "basket";
      fixed += shoot(seed, {{"free_throw_distance", line}}, kept).reason == "basket";
    }
  std::printf("from 3.6 and 4.0 m, seeds 1..100: aimed %d made, the search's swing kept %d\n",
              aimed, fixed);
  EXPECT_GE(aimed, 5);
  EXPECT_GE(aimed, fixed + 4);
}

TEST(ScriptedFreeThrow, TheReleaseTrimBringsTheBallsSpeedNearerTheSolution) {
  // 20 seeded throws from the rule's line (seeds 201..220: tuning seeds, not among the 1..200 the
  // trim was fitted on): how many leave the hands within 0.2 m/s of the ballistic solution's
  // speed, with the release trimmed by feedback and without. Measured: 17 of 20 trimmed, 1
  // untrimmed (with the cradle of before, turned to the rim: 12 and 1; over seeds 1..300, 125
  // and 24 of 300). Issue 30's "most of 20" is MostOf20ThrowsLeave... below; this asks for what
  // the trim does.
  client::FreeThrowShot untrimmed;
  untrimmed.trim_tick = 0;
  int trimmed_within = 0, untrimmed_within = 0;
  for (std::uint64_t seed = 201; seed <= 220; ++seed) {
    const Throw t = shoot(seed), u = shoot(seed, {}, untrimmed);
    trimmed_within += std::abs(t.release_speed - t.aim.launch_speed) <= 0.2;
    untrimmed_within += std::abs(u.release_speed - u.aim.launch_speed) <= 0.2;
  }
  std::printf("within 0.2 m/s of the solution, seeds 201..220: trimmed %d, untrimmed %d\n",
              trimmed_within, untrimmed_within);
  EXPECT_GE(trimmed_within, 6);
  EXPECT_GE(trimmed_within, untrimmed_within + 4);
}

TEST(ScriptedFreeThrow, TheSwingsTurnMovesTheThrowsLeftTowardsTheRimsCentre) {
  // 40 seeded throws from the rule's line (seeds 201..240: tuning seeds, not among the 1..200 the
  // trim was fitted on), with the swing turned left from the trim's tick and without: where the
  // throws that rise above the rim come down through its height, sideways. Without the turn they
  // come down right of the centre (over seeds 1..300, the straight ones 8 cm right in the median,
  // the pulled ones 0.5 m). Measured with the cradle of before (turned to the rim): median
  // 0.104 m right turned, 0.147 m unturned (23 and 24 throws); with the cradle settled alike
  // and the trunk twisted (issue 30, third round): 0.011 m left turned, 0.033 m right unturned
  // (39 and 39 throws).
  client::FreeThrowShot unturned;
  unturned.trim_turn = 0;
  std::vector<double> turned_side, unturned_side;
  for (std::uint64_t seed = 201; seed <= 240; ++seed) {
    const Throw t = shoot(seed), u = shoot(seed, {}, unturned);
    if (t.highest_m > 3.05 && !std::isnan(t.side_at_rim_m)) turned_side.push_back(t.side_at_rim_m);
    if (u.highest_m > 3.05 && !std::isnan(u.side_at_rim_m))
      unturned_side.push_back(u.side_at_rim_m);
  }
  auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  ASSERT_GE(turned_side.size(), 15u);
  ASSERT_GE(unturned_side.size(), 15u);
  const double turned = median(turned_side), before = median(unturned_side);
  std::printf(
      "side at the rim (left +), median, seeds 201..240: turned %.3f m (%zu), unturned %.3f m "
      "(%zu)\n",
      turned, turned_side.size(), before, unturned_side.size());
  EXPECT_LT(before, 0) << "without the turn the throws come down right of the centre";
  EXPECT_GE(turned, before + 0.02) << "the turn should move them left";
}

// The shooter's cradle of before issue 30's third round: the arms turned to the rim's bearing
// from the start, no twist of the trunk.
client::FreeThrowShot cradle_turned_to_the_rim() {
  client::FreeThrowShot shot;
  shot.cradle_bearing = NAN;
  shot.twist_gain = 0;
  return shot;
}

TEST(ScriptedFreeThrow, TheCradleSettlesTheBallInTheSamePlaceOfTheCupOnEverySeed) {
  // 20 seeded throws (seeds 201..220, tuning seeds): where the ball lies when the swing starts,
  // ahead of the palms' midpoint towards the rim. Throws whose ball lay less than 5 cm ahead
  // went in 1 time in 121 (seeds 1..300, the cradle of before). With the arms cradling at the
  // same bearing on every seed the ball settles alike. Measured: 5.3-5.9 cm ahead on all 20;
  // the cradle turned to the rim: 3.7-24.8 cm, 7 of 20 between 5 and 6.5 cm.
  int settled = 0, settled_before = 0;
  double lowest = 1, highest = -1;
  for (std::uint64_t seed = 201; seed <= 220; ++seed) {
    const double ahead = shoot(seed).ball_ahead_m;
    const double before = shoot(seed, {}, cradle_turned_to_the_rim()).ball_ahead_m;
    settled += ahead >= 0.05 && ahead <= 0.065;
    settled_before += before >= 0.05 && before <= 0.065;
    lowest = std::min(lowest, ahead), highest = std::max(highest, ahead);
  }
  std::printf("ball 5-6.5 cm ahead at the swing, seeds 201..220: %d (%.3f-%.3f m), before %d\n",
              settled, lowest, highest, settled_before);
  EXPECT_EQ(settled, 20);
  EXPECT_LT(highest - lowest, 0.015) << "the same place of the cup on every seed";
}

TEST(ScriptedFreeThrow, MostOf20ThrowsLeaveTheHandsWithin02MetresASecondOfTheSolution) {
  // Issue 30: a shot from the free-throw line leaves the hands within 0.2 m/s of the ballistic
  // solution's speed in most of 20 seeded throws. Seeds 201..220 (tuning seeds), the release
  // measured as the bench measures it. Measured: 17 of 20 (over seeds 1..300, 260; on unseen
  // seeds, docs/basketball.md); with the cradle turned to the rim (before): 13 of 20 here, 125
  // of 300 (42%, and 42% of 2,400 unseen seeds). Asked: 15 of 20, three in four.
  int within = 0;
  for (std::uint64_t seed = 201; seed <= 220; ++seed) {
    const Throw t = shoot(seed);
    within += std::abs(t.release_speed - t.aim.launch_speed) <= 0.2;
  }
  std::printf("within 0.2 m/s of the solution, seeds 201..220: %d of 20\n", within);
  EXPECT_GE(within, 15);
}

TEST(ScriptedFreeThrow, TheTrunksTwistTurnsTheSettledCradleTowardsTheRim) {
  // 40 seeded throws (seeds 201..240, tuning seeds) with the cradle settled at its fixed bearing,
  // with the trunk's twist and without: how far aside of the rim's centre they come down. The
  // swing flies where the trunk faces, so untwisted the throws go the same way whatever the
  // seed turned the rim by. Measured: 0.080 m aside twisted (median), 0.284 m untwisted (made:
  // 21 and 16 of the 40).
  client::FreeThrowShot untwisted;
  untwisted.twist_gain = 0;
  std::vector<double> twisted_aside, untwisted_aside;
  for (std::uint64_t seed = 201; seed <= 240; ++seed) {
    const Throw t = shoot(seed), u = shoot(seed, {}, untwisted);
    if (!std::isnan(t.side_at_rim_m)) twisted_aside.push_back(std::abs(t.side_at_rim_m));
    if (!std::isnan(u.side_at_rim_m)) untwisted_aside.push_back(std::abs(u.side_at_rim_m));
  }
  auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  ASSERT_GE(twisted_aside.size(), 30u);
  ASSERT_GE(untwisted_aside.size(), 30u);
  const double twisted = median(twisted_aside), before = median(untwisted_aside);
  std::printf(
      "aside of the rim's centre, median, seeds 201..240: twisted %.3f m, untwisted %.3f m\n",
      twisted, before);
  EXPECT_LT(twisted, 0.12);
  EXPECT_LT(twisted, 0.5 * before);
}

TEST(ScriptedFreeThrow, AimsWithTheServersBallDrag) {
  const equipment::BallSpec ball = equipment::basketball();
  EXPECT_DOUBLE_EQ(client::FreeThrowShot{}.ball_drag,
                   client::drag_per_mass(ball.radius, ball.mass, ball.drag_coefficient));
}

TEST(BasketballFreeThrow, AFallAfterTheReleaseDoesNotEndTheThrow) {
  // Random actions topple the shooter within a second or two; the ball, lobbed high away from
  // it, is still in the air then: the throw ends when it lands (a miss), not at the fall.
  auto m = sport_or_throw("basketball").create({"free_throw", 4, 0.0, {{"present_s", 0}}});
  auto& b = dynamic_cast<BasketballMatch&>(*m);
  b.ball().set_state(b.ball().position() + Vector3d(0, 1.0, 0), Vector3d(0, 0.4, 14));
  std::mt19937_64 rng(9);
  std::normal_distribution<float> noise(0, 1);
  std::vector<float> act(m->action_size());
  nlohmann::json events = nlohmann::json::array();
  for (int tick = 0; tick < 6 * 30 && !m->outcome().match_over; ++tick) {
    for (float& a : act) a = noise(rng);
    m->step({std::span<const float>(act)});
    for (const auto& e : m->outcome().info["events"]) events.push_back(e);
  }
  EXPECT_NE(find_call(events, "fall"), nullptr) << "the shooter should have fallen";
  EXPECT_EQ(m->outcome().reason, "missed");
}

}  // namespace
}  // namespace olympics::sports::basketball

namespace olympics::sports::basketball {
namespace {

TEST(ScriptedFreeThrow, TheLongShotReachesTheSolutionFrom75MetresWhereTheSetShotCannot) {
  // The team player's long shot (issue 30, fourth round: the collar bones lift the arms too) from
  // the check ball's 7.5 m (the root 7.5 m from the rim's centre), seeds 201..220 (tuning seeds,
  // not among the 1..40 its table was measured on): how many leave the hands within 0.3 m/s of
  // the speed its aim asks (the ballistic solution's plus the bias with which the release reads,
  // `long_speed_bias`), and the same for the set shot (its strongest swing, untrimmed, 7.5-8.3
  // m/s, where the solution asks about 10). Measured: 14 of 20 long shots, no set shot.
  client::FreeThrowShot long_shot, set_shot;
  long_shot.long_shot = true;
  long_shot.trim_tick = set_shot.trim_tick = 0;
  int long_within = 0, set_within = 0;
  for (std::uint64_t seed = 201; seed <= 220; ++seed) {
    const Throw l = shoot(seed, {{"free_throw_distance", 7.525}}, long_shot);
    const Throw s = shoot(seed, {{"free_throw_distance", 7.525}}, set_shot);
    ASSERT_GT(l.aim.launch_speed, 9) << "from 7.5 m the solution asks for some 10 m/s";
    long_within +=
        std::abs(l.release_speed - l.aim.launch_speed - long_shot.long_speed_bias) <= 0.3;
    set_within += std::abs(s.release_speed - s.aim.launch_speed) <= 0.3;
  }
  std::printf("from 7.5 m, seeds 201..220, within 0.3 m/s of the aim: long shot %d, set shot %d\n",
              long_within, set_within);
  EXPECT_GE(long_within, 11);
  EXPECT_EQ(set_within, 0);
}

}  // namespace
}  // namespace olympics::sports::basketball

namespace olympics::sports::basketball {
namespace {

double env_or(const char* name, double fallback) {
  const char* v = std::getenv(name);
  return v ? std::atof(v) : fallback;
}

// A hand-run probe of long shots (issue 30, fourth round): the shot's drives from the
// environment (LS_*), one line a throw. Not a check.
TEST(ScriptedFreeThrow, DISABLED_LongShotProbe) {
  client::FreeThrowShot shot;
  shot.fixed_elevation = env_or("LS_ELEV", 2.6);
  shot.trim_tick = static_cast<int>(env_or("LS_TRIM", 0));
  shot.swing_thorax = env_or("LS_THORAX", 0);
  shot.swing_trunk = env_or("LS_TRUNK", 0);
  shot.crouch_knee = env_or("LS_CROUCH", 0);
  shot.crouch_from_s = env_or("LS_CROUCH_FROM", 0.65);
  shot.swing_knee = env_or("LS_SWING_KNEE", 0);
  shot.shot_elbow = env_or("LS_ELBOW", shot.shot_elbow);
  shot.shot_s = env_or("LS_SHOT_S", shot.shot_s);
  shot.aim_offset = env_or("LS_AIM_OFFSET", shot.aim_offset);
  shot.trim_turn = env_or("LS_TURN", shot.trim_turn);
  shot.swing_yaw = env_or("LS_YAW", 0);
  shot.swing_thorax_right = env_or("LS_RIGHT", 0);
  shot.swing_thorax_yaw = env_or("LS_THORAX_YAW", 0);
  if (env_or("LS_LONG", 0) != 0) {
    shot.long_shot = true;
    shot.trim_tick = 0;
    shot.fixed_elevation = NAN;
    shot.long_speed_bias = env_or("LS_BIAS", shot.long_speed_bias);
    shot.long_aim_offset = env_or("LS_AIM_OFFSET", shot.long_aim_offset);
  }
  const double line = env_or("LS_LINE", 7.525);
  const int first = static_cast<int>(env_or("LS_FIRST", 1)),
            last = static_cast<int>(env_or("LS_LAST", 10));
  double sum = 0;
  int n = 0, falls = 0, made = 0;
  for (int seed = first; seed <= last; ++seed) {
    const Throw t = shoot(seed, {{"free_throw_distance", line}}, shot);
    const Vector3d d = t.ball_at_release - t.ball_at_swing;
    const double ahead =
        Vector3d(-t.ball_at_swing.x(), -t.ball_at_swing.y(), 0).normalized().dot(d);
    const Vector3d rim(0, 0, 3.05);
    const double needed = client::launch_speed_for(
        (rim - t.ball_at_release).head<2>().norm(), rim.z() - t.ball_at_release.z(),
        t.release_elevation_deg * M_PI / 180, shot.ball_drag);
    std::printf("needed %.2f ", needed);
    std::printf("thorax %.3f ", t.aim.thorax);
    std::printf(
        "seed %d speed %.2f angle %.1f high %.2f long %.2f side %.2f fell %d %s aim %.2f ahead "
        "%.3f up %.3f\n",
        seed, t.release_speed, t.release_elevation_deg, t.highest_m, t.long_at_rim_m,
        t.side_at_rim_m, t.fell, t.reason.c_str(), t.aim.launch_speed, ahead, d.z());
    sum += t.release_speed, ++n, falls += t.fell, made += t.reason == "basket";
  }
  std::printf("mean speed %.2f falls %d made %d of %d\n", sum / n, falls, made, n);
}

}  // namespace
}  // namespace olympics::sports::basketball
