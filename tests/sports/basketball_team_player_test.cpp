// The scripted basketball team player (clients/agent/scripted_basketball_team.h) in 1v1 games
// played in process, both slots the registry's scripted player: the attacker, given the ball at
// the first check ball, gets a shot off towards the rim, and the defender stands between it and
// the rim.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "basketball/basketball_match.h"
#include "match_info.h"
#include "policies.h"
#include "registry.h"
#include "scripted_basketball_team.h"
#include "two_policy_tick.h"

namespace olympics::sports::basketball {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

struct FirstPossession {
  double towards_rim = 0;       // m/s: the ball's fastest, horizontally towards the rim
  double top = 0;               // m: the ball's highest
  double defender_off_m = 1e9;  // at 0.8 s: the defender's root from the attacker-rim segment
};

// The first 3 s of a scripted 1v1 of `seed`: the check ball's taker shoots.
FirstPossession play_first_possession(std::uint64_t seed) {
  auto m = sport_or_throw("basketball").create({"1v1", seed, 0.0, {}});
  auto& b = dynamic_cast<BasketballMatch&>(*m);
  const client::MatchInfo info{"basketball", "1v1", m->control_dt(),
                               client::ObservationLayout::from_blocks(m->layout().observation),
                               m->action_size()};
  std::unique_ptr<client::Policy> players[2] = {client::make_policy("scripted", seed),
                                                client::make_policy("scripted", seed)};
  for (auto& p : players) p->start(info);
  const int attacker = b.referee().possession();  // 1v1: slot = side
  const Vector3d rim = b.court().rim_centre(0);
  std::vector<float> obs[2], act[2];
  FirstPossession f;
  for (int tick = 0; tick < 3 * 30 && !m->outcome().match_over; ++tick) {
    two_policy_tick(*m, players, obs, act);
    const Vector3d ball = b.ball().position(), v = b.ball().velocity();
    const Vector2d towards = (rim - ball).head<2>().normalized();
    f.top = std::max(f.top, ball.z());
    f.towards_rim = std::max(f.towards_rim, v.head<2>().dot(towards));
    if (tick == 24) {  // 0.8 s: the ball still presented or cradled, the swing not yet begun
      const core::Humanoid& a = std::as_const(b).scene().humanoid(attacker);
      const core::Humanoid& d = std::as_const(b).scene().humanoid(1 - attacker);
      const Vector2d from = a.body_state(0).position.head<2>(), to = rim.head<2>();
      const Vector2d p = d.body_state(0).position.head<2>();
      const double s = std::clamp((p - from).dot(to - from) / (to - from).squaredNorm(), 0.0, 1.0);
      f.defender_off_m = (p - (from + s * (to - from))).norm();
    }
  }
  return f;
}

TEST(ScriptedBasketballTeam, TheAttackerGetsAShotOffAndTheDefenderStandsInItsWay) {
  // Seeds 1..5 (the seeds the player was tried on). The check ball is 7.5 m out, beyond the set
  // shot's reach (it cannot walk nearer), so the shot is the long shot (the strongest swing with
  // the collar bones lifting the arms too): the ball must leave the hands towards the rim at more
  // than 4 m/s (a ball dropped or held never does) and rise above the rim. Measured: 5 of 5 off,
  // 5 above the rim (the set shot's heave of before issue 30's fourth round: 5 off at 4.5-6.9
  // m/s, 1 above the rim). The defender, put by the restart 2 m in front of the attacker, stands
  // within 0.13 m of the line from the attacker to the rim.
  int shots = 0, above_rim = 0, defended = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const FirstPossession f = play_first_possession(seed);
    shots += f.towards_rim > 4;
    above_rim += f.top > 3.05;
    defended += f.defender_off_m < 0.3;
  }
  std::printf("first possessions of seeds 1..5: %d shots off, %d above the rim, %d defended\n",
              shots, above_rim, defended);
  EXPECT_GE(shots, 4);
  EXPECT_GE(above_rim, 4);
  EXPECT_EQ(defended, 5);
}

TEST(ScriptedBasketballTeam, AScripted1v1ScoresFromTheCheckBall) {
  // Two minutes of a scripted 1v1 (seed 1, a tuning seed): the check ball's taker shoots the long
  // shot from 7.5 m, which reaches the rim (the set shot's heave never did: main before issue 30's
  // fourth round scored 0 in 5,486 heaves on unseen seeds). Measured: 4-8.
  auto m = sport_or_throw("basketball").create({"1v1", 1, 0.0, {}});
  auto& b = dynamic_cast<BasketballMatch&>(*m);
  const client::MatchInfo info{"basketball", "1v1", m->control_dt(),
                               client::ObservationLayout::from_blocks(m->layout().observation),
                               m->action_size()};
  std::unique_ptr<client::Policy> players[2] = {client::make_policy("scripted", 1),
                                                client::make_policy("scripted", 1)};
  for (auto& p : players) p->start(info);
  std::vector<float> obs[2], act[2];
  for (int tick = 0; tick < 120 * 30 && !m->outcome().match_over; ++tick) {
    two_policy_tick(*m, players, obs, act);
  }
  const auto& score = b.referee().score();
  std::printf("seed 1, 120 s: %d-%d\n", score[0], score[1]);
  EXPECT_GE(score[0] + score[1], 4) << "two baskets from behind the arc in two minutes";
}

}  // namespace
}  // namespace olympics::sports::basketball

namespace olympics::sports::basketball {
namespace {

// A hand-run probe (issue 30, fourth round): a scripted 1v1 of GP_SECONDS (seed GP_SEED), one line
// per restart: where the ball was presented (m from the rim), how long until the next, whether
// the score changed, where the ball first came down through 13 cm above the rim. Not a check.
TEST(ScriptedBasketballTeam, DISABLED_GameProbe) {
  const std::uint64_t seed = std::getenv("GP_SEED") ? std::atoi(std::getenv("GP_SEED")) : 1;
  const double seconds = std::getenv("GP_SECONDS") ? std::atof(std::getenv("GP_SECONDS")) : 120;
  auto m = sport_or_throw("basketball").create({"1v1", seed, 0.0, {}});
  auto& b = dynamic_cast<BasketballMatch&>(*m);
  const client::MatchInfo info{"basketball", "1v1", m->control_dt(),
                               client::ObservationLayout::from_blocks(m->layout().observation),
                               m->action_size()};
  client::FreeThrowShot shot;
  if (const char* v = std::getenv("GP_OFFSET")) shot.long_aim_offset = std::atof(v);
  if (const char* v = std::getenv("GP_BIAS")) shot.long_speed_bias = std::atof(v);
  std::unique_ptr<client::Policy> players[2] = {
      std::make_unique<client::ScriptedBasketballTeamPlayer>(shot),
      std::make_unique<client::ScriptedBasketballTeamPlayer>(shot)};
  for (auto& p : players) p->start(info);
  const Vector3d rim = b.court().rim_centre(0);
  std::vector<float> obs[2], act[2];
  std::vector<double> longs, sides;
  int shots = 0, made = 0;
  bool was_presenting = false;
  double since = 0, long_m = NAN, side_m = NAN, top = 0;
  int points_before = 0;
  Vector3d spot = Vector3d::Zero();
  auto report = [&](double now) {
    const int points = b.referee().score()[0] + b.referee().score()[1];
    if (std::getenv("GP_VERBOSE"))
      std::printf("from %.2f m at %.1f s: %.1f s, top %.2f, long %.2f side %.2f, +%d\n",
                  (spot - rim).head<2>().norm(), since, now - since, top, long_m, side_m,
                  points - points_before);
    if ((spot - rim).head<2>().norm() > 6) {
      ++shots, made += points > points_before;
      if (!std::isnan(long_m)) longs.push_back(long_m), sides.push_back(side_m);
    }
    points_before = points;
  };
  for (int tick = 0; tick < seconds * 30 && !m->outcome().match_over; ++tick) {
    two_policy_tick(*m, players, obs, act);
    const double now = tick / 30.0;
    if (b.presenting() && !was_presenting) {
      if (tick > 0) report(now);
      since = now, spot = b.present_spot(), long_m = side_m = NAN, top = 0;
    }
    was_presenting = b.presenting();
    const Vector3d ball = b.ball().position();
    top = std::max(top, ball.z());
    if (std::isnan(long_m) && top > 3.3 && b.ball().velocity().z() < 0 && ball.z() < 3.18) {
      const Vector2d towards = (rim - spot).head<2>().normalized();
      const Vector2d d = (ball - rim).head<2>();
      long_m = towards.dot(d), side_m = towards.x() * d.y() - towards.y() * d.x();
    }
  }
  auto median = [](std::vector<double> v) {
    if (v.empty()) return double{NAN};
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  int near = 0;
  for (size_t i = 0; i < longs.size(); ++i) near += std::hypot(longs[i], sides[i]) < 0.3;
  std::printf("score %d-%d long shots %d made %d came down within 0.3 m %d long %.2f side %.2f\n",
              b.referee().score()[0], b.referee().score()[1], shots, made, near, median(longs),
              median(sides));
}

}  // namespace
}  // namespace olympics::sports::basketball
