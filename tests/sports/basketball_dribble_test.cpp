// The standing dribble (clients/agent/scripted_basketball_dribble.h): the tally that counts
// dribbles from the ball's true state, and the scripted dribbler at the first check ball of a 1v1
// played in process (the other slot the scripted team player, standing as the defender).
#include <gtest/gtest.h>

#include <cstdio>

#include "basketball/basketball_match.h"
#include "match_info.h"
#include "registry.h"
#include "scripted_basketball_dribble.h"
#include "scripted_basketball_team.h"
#include "two_policy_tick.h"

namespace olympics::client {
namespace {

// A ball's height and vertical velocity at 30 Hz under gravity alone, from `height` at `vz`,
// until it is back at the floor (its centre 0.12 m up), fed to `tally` (`apart` from the root).
void fall_to_floor(DribbleTally& tally, double height, double vz, double apart = 0.5) {
  constexpr double dt = 1.0 / 30;
  while (height > 0.12) {
    tally.tick(height, vz, apart);
    vz -= 9.81 * dt;
    height += vz * dt;
  }
}

// Up from the floor at `vz` until the tick at which the ball rises no more than `until_vz`.
double rise(DribbleTally& tally, double vz, double until_vz, double apart = 0.5) {
  constexpr double dt = 1.0 / 30;
  double height = 0.15;
  while (vz > until_vz) {
    tally.tick(height, vz, apart);
    vz -= 9.81 * dt;
    height += vz * dt;
  }
  return height;
}

TEST(DribbleTally, CountsAHandPushAfterEachBounce) {
  DribbleTally tally;
  fall_to_floor(tally, 1.2, 0);        // the presented ball drops
  double top = rise(tally, 3.9, 0.5);  // bounces up; the hand meets it on its way up
  fall_to_floor(tally, top, -3.5);     // pushed down
  EXPECT_EQ(tally.dribbles(), 1);
  top = rise(tally, 4.2, 0.5);
  fall_to_floor(tally, top, -3.5);
  EXPECT_EQ(tally.dribbles(), 2);
  EXPECT_FALSE(tally.lost());
}

TEST(DribbleTally, GravityAloneIsNoPushAndASecondBounceLosesTheBall) {
  DribbleTally tally;
  fall_to_floor(tally, 1.2, 0);
  rise(tally, 3.9, -10);  // up through its apex and down again, untouched
  EXPECT_EQ(tally.dribbles(), 0);
  EXPECT_FALSE(tally.lost());
  tally.tick(0.14, 2.5, 0.5);  // the second bounce
  EXPECT_TRUE(tally.lost());
}

TEST(DribbleTally, ABallFarFromThePlayerIsLost) {
  DribbleTally tally;
  tally.tick(1.2, 0, 0.5);
  EXPECT_FALSE(tally.lost());
  tally.tick(1.1, -1, DribbleTally::kLostApart_m + 0.05);
  EXPECT_TRUE(tally.lost());
}

struct Episode {
  int dribbles = 0;
  bool fell = false;
};

// The first check ball of a 1v1 of `seed`, its taker the scripted dribbler, for `seconds`.
Episode dribble_at_the_check_ball(std::uint64_t seed, double seconds) {
  auto m = sports::sport_or_throw("basketball").create({"1v1", seed, 0.0, {}});
  auto& b = dynamic_cast<sports::basketball::BasketballMatch&>(*m);
  const MatchInfo info{"basketball", "1v1", m->control_dt(),
                       ObservationLayout::from_blocks(m->layout().observation), m->action_size()};
  const int dribbler = b.referee().possession();  // 1v1: slot = side
  ScriptedDribbler dribbling;
  ScriptedBasketballTeamPlayer standing;
  Policy* players[2];
  players[dribbler] = &dribbling, players[1 - dribbler] = &standing;
  for (auto* p : players) p->start(info);
  DribbleTally tally;
  Episode e;
  std::vector<float> obs[2], act[2];
  for (int tick = 0; tick < seconds * 30 && !m->outcome().match_over; ++tick) {
    sports::two_policy_tick(*m, players, obs, act);
    if (m->outcome().info.contains("events"))
      for (const auto& ev : m->outcome().info["events"])
        if (ev.value("call", "") == "fall" && ev.value("slot", -1) == dribbler) e.fell = true;
    const Eigen::Vector3d ball = b.ball().position();
    const Eigen::Vector3d root = std::as_const(b).scene().humanoid(dribbler).body_state(0).position;
    tally.tick(ball.z(), b.ball().velocity().z(), (ball - root).head<2>().norm());
  }
  e.dribbles = tally.dribbles();
  return e;
}

// Of tuning seeds 1..5, how many dribbled at least `at_least` times in the first `seconds`.
int seeds_with_dribbles(int at_least, double seconds) {
  int seeds = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const Episode e = dribble_at_the_check_ball(seed, seconds);
    std::printf("seed %d: %d dribbles%s\n", static_cast<int>(seed), e.dribbles,
                e.fell ? ", fell" : "");
    seeds += e.dribbles >= at_least;
  }
  return seeds;
}

TEST(ScriptedDribble, TheCheckBallsTakerBouncesItOffItsHand) {
  // Tuning seeds 1..5, the first 2 s. The presented ball dropped, bounced and pushed back down by
  // the right hand: at least one dribble on each seed. Measured: 5 of 5 (1-2 each). What it does
  // not yet do, so not asserted (docs/basketball.md, "The standing dribble"): keep the ball (it
  // is lost after one or two) or stay up (it falls 1.8-2.2 s in, after the first push or two).
  EXPECT_EQ(seeds_with_dribbles(1, 2.0), 5);
}

TEST(ScriptedDribble, WithTheAnklesCappedItDribblesTwiceOnMostSeeds) {
  // Tuning seeds 1..5, the first 2.5 s. The reach carries the centre of mass to the front of the
  // feet, where the standing balance's ankle push lifts the heels; with that push capped
  // (DribbleParams::max_toes_down) the ball comes back to the hand a second time before the
  // fall. Measured: two or more on 3 of 5 seeds; uncapped (main's dribble) on 1 of 5.
  EXPECT_GE(seeds_with_dribbles(2, 2.5), 3);
}

}  // namespace
}  // namespace olympics::client
