// DIAG (local, not committed): where the scripted boxer's punches go.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <nlohmann/json.hpp>

#include "boxing/boxing_match.h"
#include "core/control_rate.h"
#include "registry.h"
#include "scripted_boxing.h"
#include "smpl_observation.h"

namespace olympics::client {
namespace {

struct Throw {
  int slot, hand;
  double t0, dist0, bearing0;
  double min_head = 9, min_chest = 9, min_glove = 9;
  bool arrival = false, scored = false, blocked_first = false, own_fall = false, opp_fall = false;
  double arr_speed = 0, arr_kn = 0, arr_force = 0;
  std::string arr_body;
};

TEST(BoxDiag, DISABLED_Where) {
  const int s0 = std::atoi(std::getenv("S0") ? std::getenv("S0") : "1");
  const int s1 = std::atoi(std::getenv("S1") ? std::getenv("S1") : "8");
  const double secs = std::atof(std::getenv("SECS") ? std::getenv("SECS") : "300");
  std::map<std::string, int> cls;
  int tot_p = 0, tot_f = 0;
  double planted = 0, ticks_all = 0;
  std::vector<double> dists;
  for (int seed = s0; seed <= s1; ++seed) {
    auto match = sports::sport_or_throw("boxing").create({"1v1", (std::uint64_t)seed, 0.0, {}});
    auto* bm = dynamic_cast<sports::boxing::BoxingMatch*>(match.get());
    const auto layout = ObservationLayout::from_blocks(match->layout().observation);
    ScriptedBoxingPolicy players[2];
    for (auto& p : players) p.start({"boxing", "1v1", core::kControlDt, layout, 69});
    std::vector<float> obs[2] = {std::vector<float>(match->obs_size()),
                                 std::vector<float>(match->obs_size())};
    std::vector<float> act[2] = {std::vector<float>(69), std::vector<float>(69)};
    std::vector<Throw> throws;
    std::array<int, 2> open = {-1, -1};  // index of the throw under way per slot
    size_t seen_arrivals = 0;
    int p = 0, f = 0;
    const int off = layout.offset("opponent_root", "position");
    for (int tick = 0; tick < secs * 30 && !match->outcome().match_over; ++tick) {
      const double t = tick / 30.0;
      for (int s = 0; s < 2; ++s) {
        match->observe(s, obs[s]);
        players[s].act(obs[s], act[s]);
        planted += players[s].planted();
        ticks_all += 1;
        const auto arm = players[s].punching();
        const int hand = arm ? (*arm == Arm::Right ? 1 : 0) : -1;
        if (hand >= 0 &&
            (open[s] < 0 || throws[open[s]].hand != hand || t - throws[open[s]].t0 > 0.5)) {
          Throw th{s,
                   hand,
                   t,
                   std::hypot(obs[s][off], obs[s][off + 1]),
                   std::atan2(obs[s][off + 1], obs[s][off]),
                   9,
                   9,
                   9,
                   false,
                   false,
                   false,
                   false,
                   false,
                   0,
                   0,
                   0,
                   ""};
          throws.push_back(th);
          open[s] = throws.size() - 1;
        }
      }
      if (std::getenv("TRACE") && tick % 15 == 0) {
        const int vel = smpl::kSelf.linear_velocity(0);
        std::printf(
            "t %5.1f d %.2f b %+.2f %+.2f v %.2f %.2f pl %d%d st %d%d h %.2f %.2f\n", t,
            std::hypot(obs[0][off], obs[0][off + 1]), std::atan2(obs[0][off + 1], obs[0][off]),
            std::atan2(obs[1][off + 1], obs[1][off]), std::hypot(obs[0][vel], obs[0][vel + 1]),
            std::hypot(obs[1][vel], obs[1][vel + 1]), players[0].planted(), players[1].planted(),
            players[0].stepping(), players[1].stepping(), smpl::root_height(obs[0]),
            smpl::root_height(obs[1]));
      }
      match->step({std::span<const float>(act[0]), std::span<const float>(act[1])});
      // distances for open throws (0.45 s window)
      const auto& scene = static_cast<const sports::boxing::BoxingMatch*>(bm)->scene();
      for (int s = 0; s < 2; ++s) {
        if (open[s] < 0) continue;
        Throw& th = throws[open[s]];
        if (t - th.t0 > 0.45) continue;
        const Eigen::Vector3d g = bm->glove_position(s, th.hand);
        const auto& opp = scene.humanoid(1 - s);
        th.min_head = std::min(th.min_head, (g - opp.body_state(smpl::kHead).position).norm());
        th.min_chest = std::min(th.min_chest, (g - opp.body_state(smpl::kChest).position).norm());
        const double dg = std::min((g - bm->glove_position(1 - s, 0)).norm(),
                                   (g - bm->glove_position(1 - s, 1)).norm());
        if (dg < 0.2 && !th.arrival && th.min_glove >= 0.2) th.blocked_first = true;
        th.min_glove = std::min(th.min_glove, dg);
      }
      const auto& arrs = bm->arrivals();
      for (; seen_arrivals < arrs.size(); ++seen_arrivals) {
        const auto& a = arrs[seen_arrivals];
        const int s = a.attacker;
        if (open[s] < 0) continue;
        Throw& th = throws[open[s]];
        if (th.hand != a.hand || t - th.t0 > 0.45 || th.arrival) continue;
        th.arrival = true;
        th.arr_speed = a.closing_speed;
        th.arr_kn = std::acos(std::clamp(a.knuckle_cos, -1.0, 1.0)) * 57.3;
        th.arr_force = a.force;
        th.arr_body = std::to_string(a.target_body);
      }
      for (const auto& ev : match->outcome().info.value("events", nlohmann::json::array())) {
        const std::string c = ev.value("call", "");
        if (c == "punch") {
          ++p;
          const int s = ev.value("slot", 0);
          if (open[s] >= 0 && t - throws[open[s]].t0 < 0.5) throws[open[s]].scored = true;
        }
        if (c == "fall") {
          ++f;
          const int s = ev.value("slot", 0);
          for (auto& th : throws)
            if (t - th.t0 < 2.0 && t >= th.t0) (th.slot == s ? th.own_fall : th.opp_fall) = true;
          std::printf("FALL seed %d slot %d t %.1f d %.2f planted %d %d\n", seed, s, t,
                      std::hypot(obs[0][off], obs[0][off + 1]), players[0].planted(),
                      players[1].planted());
        }
      }
    }
    for (const auto& th : throws) {
      std::string k;
      if (th.scored)
        k = "scored";
      else if (th.arrival)
        k = "arrived-not-blow";
      else if (th.blocked_first)
        k = "blocked";
      else if (std::min(th.min_head - 0.2, th.min_chest - 0.2) > 0.0)
        k = "short";
      else
        k = "miss-other";
      ++cls[k];
      if (th.own_fall) ++cls["(own fall <2s)"];
      if (th.opp_fall) ++cls["(opp fall <2s)"];
      if (std::getenv("VERBOSE"))
        std::printf(
            "seed %d slot %d hand %d t %.1f d %.2f b %.2f head %.2f chest %.2f glove %.2f %s %s "
            "%.2f/%.0f/%.0f %s%s\n",
            seed, th.slot, th.hand, th.t0, th.dist0, th.bearing0, th.min_head, th.min_chest,
            th.min_glove, k.c_str(), th.arr_body.c_str(), th.arr_speed, th.arr_kn, th.arr_force,
            th.own_fall ? "OWNFALL " : "", th.opp_fall ? "OPPFALL" : "");
    }
    std::printf("seed %d: punches %d falls %d throws %zu min %.2f\n", seed, p, f, throws.size(),
                match->tick() / 1800.0);
    tot_p += p;
    tot_f += f;
  }
  std::printf("TOTAL punches %d falls %d planted %.3f\n", tot_p, tot_f, planted / ticks_all);
  for (const auto& [k, v] : cls) std::printf("  %s: %d\n", k.c_str(), v);
}

}  // namespace
}  // namespace olympics::client
