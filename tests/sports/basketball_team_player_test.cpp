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
    for (int s = 0; s < 2; ++s) {
      obs[s].resize(m->obs_size()), act[s].resize(m->action_size());
      m->observe(s, obs[s]);
      players[s]->act(obs[s], act[s]);
    }
    m->step({std::span<const float>(act[0]), std::span<const float>(act[1])});
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
  // shot's reach (it cannot walk nearer), so the shot is the strongest swing, a heave: the ball
  // must leave the hands towards the rim at more than 4 m/s (a ball dropped or held never does).
  // Measured: 4.5 to 6.9 m/s on all 5; only seed 3's rises above the rim's height (the swing
  // leaves the ball flat unless the fingers strike it a second time: docs/basketball.md). The
  // defender, put by the restart 2 m in front of the attacker, stands within 0.13 m of the line
  // from the attacker to the rim.
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
  EXPECT_EQ(defended, 5);
}

}  // namespace
}  // namespace olympics::sports::basketball
