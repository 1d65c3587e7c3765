// The scripted tennis player's swing (clients/agent/scripted_tennis_swing.h): the arm's turn
// about the shoulder, and that it meets balls it can reach.
#include "scripted_tennis_swing.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "core/control_rate.h"
#include "racket_match_harness.h"
#include "registry.h"
#include "scripted_racket.h"

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

}  // namespace
}  // namespace olympics::client
