// The scripted fencer and boxer on fixed seeds: most of the fencer's exchanges end with a touch
// by the tip rather than a fall; the boxer stays up through most first rounds and throws its
// punches at the chest, within reach, with the trunk leaning and turned into them.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/control_rate.h"
#include "registry.h"
#include "scripted_boxing.h"
#include "scripted_fencing.h"
#include "smpl_observation.h"

namespace olympics::client {
namespace {

// Two scripted players of `sport` on `seed` for at most `seconds` of play: every referee call.
// `watch(layout, slot, player, observation, action)` is called after each player's act().
template <class Player, class Watch>
std::vector<nlohmann::json> play_bout(const std::string& sport, std::uint64_t seed, double seconds,
                                      Watch watch) {
  auto match = sports::sport_or_throw(sport).create({"1v1", seed, 0.0, {}});
  const auto layout = ObservationLayout::from_blocks(match->layout().observation);
  Player players[2];
  for (auto& p : players) p.start({sport, "1v1", core::kControlDt, layout, 69});
  std::vector<float> obs[2] = {std::vector<float>(match->obs_size()),
                               std::vector<float>(match->obs_size())};
  std::vector<float> act[2] = {std::vector<float>(69), std::vector<float>(69)};
  std::vector<nlohmann::json> calls;
  for (int tick = 0; tick < seconds * 30 && !match->outcome().match_over; ++tick) {
    for (int s = 0; s < 2; ++s) {
      match->observe(s, obs[s]);
      players[s].act(obs[s], act[s]);
      watch(layout, s, std::as_const(players[s]), std::span<const float>(obs[s]),
            std::span<const float>(act[s]));
    }
    match->step({std::span<const float>(act[0]), std::span<const float>(act[1])});
    for (const auto& ev : match->outcome().info.value("events", nlohmann::json::array()))
      calls.push_back(ev);
  }
  return calls;
}

template <class Player>
std::vector<nlohmann::json> calls_of_a_bout(const std::string& sport, std::uint64_t seed,
                                            double seconds) {
  return play_bout<Player>(sport, seed, seconds, [](auto&&...) {});
}

TEST(ScriptedFencingPolicy, MostExchangesEndWithATouchByTheTipNotAFall) {
  // The first four exchanges of three bouts: each ends with a touch by the tip (a point for a
  // touch or a double) or a halt (off the piste, a fall, ...). Most are touches, and more
  // touches than falls. (The fencer walking at 1.2 m/s: 7 touches and 4 falls in 12; a toolkit
  // fencer that made 11 and 1 here fell more often on unseen seeds: docs/combat-sports.md.)
  int touches = 0, falls = 0, exchanges = 0;
  for (std::uint64_t seed : {1, 2, 3}) {
    int seen = 0;
    for (const auto& c : calls_of_a_bout<ScriptedFencingPolicy>("fencing", seed, 30)) {
      const std::string call = c.value("call", "");
      if (seen >= 4 || (call != "point" && call != "halt")) continue;
      ++seen, ++exchanges;
      if (call == "point" && c.value("reason", "") != "fall") ++touches;
      if (call == "halt" && c.value("reason", "") == "fall") ++falls;
    }
  }
  EXPECT_GE(exchanges, 9);
  EXPECT_GT(2 * touches, exchanges) << "exchanges ending with a touch by the tip";
  EXPECT_GT(touches, falls) << "exchanges halted by a fall";
}

TEST(ScriptedFencingPolicy, FencersStayUpThroughTheirFirstHalfMinutes) {
  // The first 30 s of eight bouts: at most one fall in all, and touches by the tip in half the
  // bouts at least (5 of 8 here: slower fencers take longer to meet). The fencer that walked at
  // 1.2 m/s fell 14 times here, most within 3 s of an "en garde", as both rushed in.
  int falls = 0, bouts_with_a_touch = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    int touches = 0;
    for (const auto& c : calls_of_a_bout<ScriptedFencingPolicy>("fencing", seed, 30)) {
      const std::string call = c.value("call", "");
      falls += call == "fall";
      touches += call == "point" && c.value("reason", "") != "fall";
    }
    bouts_with_a_touch += touches > 0;
  }
  EXPECT_LE(falls, 1) << "falls in 8 x 30 s";
  EXPECT_GE(bouts_with_a_touch, 4) << "of 8 bouts";
}

TEST(ScriptedBoxingPolicy, MostBoutsGoThroughTheFirstRoundWithoutAKnockDown) {
  // Eight bouts' first round (60 s): most go through it without either boxer down. The boxer
  // walks into range and plants both feet to punch; the previous one (punching as it stepped)
  // was knocked down in every one of these rounds. Now: 5 clean rounds of 8 (6 with the punch
  // at the head and the chest before issue 30's third round: one seed's round differs, within
  // the noise of the unseen figures, docs/combat-sports.md). (This test also
  // wanted 3 scoring punches a clean round: those were guard gloves pressed on a head, which no
  // longer score: the scripted boxer's punches rarely land, docs/combat-sports.md.)
  int clean_rounds = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    bool knocked_down = false;
    for (const auto& c : calls_of_a_bout<ScriptedBoxingPolicy>("boxing", seed, 60))
      knocked_down = knocked_down || c.value("call", "") == "knockdown";
    clean_rounds += !knocked_down;
  }
  EXPECT_GE(clean_rounds, 5) << "of 8 first rounds without a knock-down";
}

// Two scripted boxers on `seed` for the first minute, watched (play_bout).
template <class Watch>
void watch_first_minute(std::uint64_t seed, Watch watch) {
  play_bout<ScriptedBoxingPolicy>("boxing", seed, 60, watch);
}

TEST(ScriptedBoxingPolicy, PunchesAtTheChestWithTheTrunkInThemAndOnlyWithinReach) {
  // Every punch the boxer throws in the first minute of 16 bouts (an arm straightened out of
  // the guard): at the opponent's chest, under its guard, never at a chest further than 0.9 m
  // from the shoulder, with the trunk (torso, spine, chest) pitched forward 0.4 rad and the
  // punching shoulder turned forward 0.4 rad. Main's boxer threw at the head and the chest in
  // turn with the trunk upright, from as far as 1.1 m root to root: 34 of its 82 punches on
  // seeds 1-40 fell short and 40 met the other's glove first (docs/combat-sports.md).
  int throws = 0, beyond_reach = 0, upright = 0;
  for (std::uint64_t seed = 1; seed <= 16; ++seed)
    watch_first_minute(seed, [&](const ObservationLayout& layout, int, const ScriptedBoxingPolicy&,
                                 std::span<const float> obs, std::span<const float> act) {
      const int chest = layout.offset("opponent_targets", "chest");
      for (int elbow : {smpl::kLElbow, smpl::kRElbow}) {
        if (std::abs(smpl::joint_angle(act, elbow, 2)) > 0.5) continue;  // guard: 1.8
        ++throws;
        const int shoulder = elbow == smpl::kRElbow ? smpl::kRShoulder : smpl::kLShoulder;
        const Eigen::Vector3d to_chest =
            smpl::vec3(obs, chest) - smpl::body_position(obs, shoulder);
        beyond_reach += to_chest.norm() > 0.9;
        double pitch = 0, turn = 0;
        for (int j : {int(smpl::kTorso), smpl::kTorso + 1, int(smpl::kChest)}) {
          pitch += smpl::joint_angle(act, j, 1);
          turn += smpl::joint_angle(act, j, 2);
        }
        const double forward = elbow == smpl::kRElbow ? 0.4 : -0.4;
        upright += std::abs(pitch - 0.4) > 0.01 || std::abs(turn - forward) > 0.01;
      }
    });
  EXPECT_GE(throws, 20) << "ticks with an arm thrown (29 here: a punch is out 8 ticks)";
  EXPECT_EQ(beyond_reach, 0) << "of " << throws << " thrown at a chest beyond 0.9 m";
  EXPECT_EQ(upright, 0) << "of " << throws << " thrown without the trunk leaning and turned";
}

TEST(ScriptedBoxingPolicy, PlantsOnlyWhenNotBackingOff) {
  // Every time a boxer plants both feet in the first minute of 16 bouts, it is not moving away
  // from the opponent faster than 5 cm/s. Main's boxer planted while backing off at 0.2-0.3 m/s,
  // its centre of mass near its heels, and tipped over backward within a second with no one
  // touching it (12 of its 50 falls on seeds 1-80, docs/combat-sports.md); on these bouts 9 of
  // its 18 plants were made backing off.
  int plants = 0, backing_off = 0;
  for (std::uint64_t seed = 1; seed <= 16; ++seed) {
    bool was_planted[2] = {false, false};
    watch_first_minute(
        seed, [&](const ObservationLayout& layout, int slot, const ScriptedBoxingPolicy& boxer,
                  std::span<const float> obs, std::span<const float>) {
          const bool plants_now = boxer.planted() && !was_planted[slot];
          was_planted[slot] = boxer.planted();
          if (!plants_now) return;
          ++plants;
          const int opponent = layout.offset("opponent_root", "position");
          const Eigen::Vector2d towards = smpl::vec3(obs, opponent).head<2>().normalized();
          backing_off += smpl::root_velocity(obs).head<2>().dot(towards) < -0.05;
        });
  }
  EXPECT_GE(plants, 10) << "plants in 16 first minutes";
  EXPECT_EQ(backing_off, 0) << "of " << plants << " plants made backing off faster than 5 cm/s";
}

}  // namespace
}  // namespace olympics::client
