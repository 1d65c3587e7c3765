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

// The face's speed along the stroke's line at the planned contact, over the speed planned, for the
// first ball of a tennis ball-return episode: the face centre as the observation shows it, over
// the tick before the planned contact. None: no stroke within reach met its planned time.
std::optional<double> face_speed_share_at_contact(std::uint64_t seed) {
  ScriptedRacketPlay play("tennis", {"ball_return", seed, 10.0, {}});
  const auto& layout = play.layout;
  const int x = layout.offset("court_position", "x"), y = layout.offset("court_position", "y");
  const int cos = layout.offset("court_heading", "cos"),
            sin = layout.offset("court_heading", "sin");
  const int racket = layout.offset("racket_position", "position");
  Eigen::Vector3d last_face = Eigen::Vector3d::Zero();
  std::optional<double> share;
  bool over = false;
  while (!play.over() && !over && !share) {
    const auto events = play.tick([&](int) {
      const auto& o = play.obs[0];
      control::CourtFrame court;
      court.root = {o[x], o[y], 0};
      court.yaw = std::atan2(o[sin], o[cos]);
      const Eigen::Vector3d face =
          court.point(Eigen::Vector3d(o[racket], o[racket + 1], o[racket + 2]));
      const auto& stroke = play.players[0].stroke();
      if (stroke && stroke->reachable && stroke->pivot && !stroke->serve && stroke->speed > 0 &&
          std::abs(stroke->time_to_hit) <= 0.5 * core::kControlDt + 1e-9)
        share = ((face - last_face) / core::kControlDt).dot(stroke->direction) / stroke->speed;
      last_face = face;
    });
    for (const auto& ev : events) {
      const std::string call = ev.value("call", "");
      if (call == "return_in" || call == "point") over = true;
    }
  }
  return share;
}

// Ball-return tuning seeds whose first ball the legs bring within reach early, then step the last
// 0.1-0.3 m to its stance until they stop 0.5 s before contact. Holding the swing back until then,
// the arm was still drawing back to the backswing as the forward turn began, and the face met the
// ball at a median 0.7 of the planned speed; counted as settled within 0.3 m of the stance, the
// swing starts about 0.75 s before contact and the face meets the ball at about the planned speed
// (issue 29, the swing-start round; docs/racket-sports.md).
TEST(ScriptedTennisSwing, DrawsTheBackswingInTimeWhileTheLegsStepTheLastFewCm) {
  std::vector<double> shares;
  for (std::uint64_t seed : {3, 21, 87, 148, 234, 283, 285}) {
    const auto share = face_speed_share_at_contact(seed);
    std::printf("seed %d: face speed at contact %.2f of the plan\n", int(seed),
                share.value_or(NAN));
    if (share) shares.push_back(*share);
  }
  ASSERT_GE(shares.size(), 5u);  // the case under test: these balls are swung at
  std::sort(shares.begin(), shares.end());
  EXPECT_GE(shares[shares.size() / 2], 0.95);  // main: 0.84 (0.63-0.92); now 1.02 (0.75-1.35)
}

}  // namespace
}  // namespace olympics::client
