// The scripted tennis player's swing (clients/agent/scripted_tennis_swing.h): the arm's turn
// about the shoulder, and that it meets balls it can reach.
#include "scripted_tennis_swing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "control/ball_path.h"
#include "core/control_rate.h"
#include "registry.h"
#include "scripted_racket.h"
#include "scripted_racket_play.h"

namespace olympics::client {
namespace {

TEST(ScriptedTennisSwing, TurnsFromRestToTheContactRateAtContact) {
  const double rate = 10, back = 1.2, follow = 0.5;
  EXPECT_DOUBLE_EQ(swing_turn(-1.0, rate, back, follow).angle, -back);
  EXPECT_DOUBLE_EQ(swing_turn(-1.0, rate, back, follow).rate, 0);
  // It starts from rest 2 back / rate before contact, and reaches the ball at the contact rate.
  EXPECT_NEAR(swing_turn(-2 * back / rate + 1e-9, rate, back, follow).rate, 0, 1e-6);
  EXPECT_NEAR(swing_turn(0, rate, back, follow).angle, 0, 1e-12);
  EXPECT_NEAR(swing_turn(0, rate, back, follow).rate, rate, 1e-12);
  // The angle is the integral of the rate (a tick's steps, within a small fraction of a radian).
  double angle = -back;
  for (double tau = -0.3; tau < 0.1; tau += 0.001)
    angle += 0.001 * swing_turn(tau + 0.0005, rate, back, follow).rate;
  EXPECT_NEAR(angle, swing_turn(0.1, rate, back, follow).angle, 0.01);
  EXPECT_DOUBLE_EQ(swing_turn(0.2, rate, back, follow).angle, follow);
}

// Ball-return seeds (tuning seeds) whose first ball the player plans a stroke within reach for:
// of these 11 first balls the racket touched 1 (seed 87) with the swing solved by inverse
// kinematics every tick along the arc (the player before issue 29's fourth round), 4 with the arm
// turned in joint space.
TEST(ScriptedTennisSwing, TouchesFirstBallsItCanReach) {
  int touched = 0;
  for (std::uint64_t seed : {3, 11, 12, 21, 32, 77, 87, 90, 97, 99, 100}) {
    ScriptedRacketPlay play("tennis", {"ball_return", seed, 10.0, {}});
    bool over = false, touch = false;
    while (!play.over() && !over) {
      for (const auto& ev : play.tick()) {
        const std::string call = ev.value("call", "");
        if (call == "hit") touch = true;
        if (call == "return_in" || call == "point") over = true;
      }
    }
    touched += touch;
  }
  std::printf("first balls touched: %d of 11\n", touched);
  EXPECT_GE(touched, 3);
}

// The face at contact: the angle between the face's normal (the observation's racket normal, the
// tick before the hit) and the normal planned. With the swing asked 0.033 s ahead of the ball and
// held after 0.5 rad of follow-through, the arm still lagged the turn at contact: the face met
// the ball turned back from the plan (a median 17 degrees off on these seeds), slower along its
// normal, and most such balls fell short of the net (issue 29, face round); now 10 degrees.
// The tuning seeds (1-400) whose first ball both the player before the face round and this one
// touched with a stroke planned within reach.
constexpr std::uint64_t kFaceSeeds[] = {87, 147, 170, 234, 283, 326, 327, 359, 364, 365, 393};

TEST(ScriptedTennisSwing, MeetsTheBallWithTheFaceItPlanned) {
  std::vector<double> off_deg;
  for (std::uint64_t seed : kFaceSeeds) {
    ScriptedRacketPlay play("tennis", {"ball_return", seed, 10.0, {}});
    const int normal_at = play.layout.offset("racket_normal");
    const int cos_at = play.layout.offset("court_heading", "cos");
    const int sin_at = play.layout.offset("court_heading", "sin");
    std::optional<ScriptedRacketPolicy::Stroke> stroke;
    Eigen::Vector3d face_normal = Eigen::Vector3d::Zero();
    bool over = false, hit = false;
    while (!play.over() && !over) {
      const auto events = play.tick([&](int) {
        const auto& o = play.obs[0];
        control::CourtFrame court;
        court.yaw = std::atan2(o[sin_at], o[cos_at]);
        face_normal =
            court.vector(Eigen::Vector3d(o[normal_at], o[normal_at + 1], o[normal_at + 2]));
        stroke = play.players[0].stroke();
      });
      for (const auto& ev : events) {
        const std::string call = ev.value("call", "");
        if (call == "hit" && !hit && stroke && stroke->reachable) {
          hit = true;
          const double cosine = std::abs(face_normal.normalized().dot(stroke->normal));
          off_deg.push_back(std::acos(std::min(1.0, cosine)) * 180 / M_PI);
        }
        if (call == "return_in" || call == "point") over = true;
      }
    }
  }
  ASSERT_GE(off_deg.size(), 4u) << "too few balls touched to judge the face";
  std::sort(off_deg.begin(), off_deg.end());
  const double median = off_deg[off_deg.size() / 2];
  std::printf("face normal off the plan at contact: median %.1f degrees over %zu hits\n", median,
              off_deg.size());
  EXPECT_LE(median, 12.0);
}

}  // namespace
}  // namespace olympics::client
