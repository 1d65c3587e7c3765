// The racket policy tests' match harness: a match of `sport` in process with every slot played by
// a scripted racket player (ScriptedRacketPolicy), stepped a tick at a time.
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/control_rate.h"
#include "registry.h"
#include "scripted_racket.h"

namespace olympics::client {

struct ScriptedRacketPlay {
  ScriptedRacketPlay(const std::string& sport, const sports::MatchSettings& settings)
      : match(sports::sport_or_throw(sport).create(settings)),
        layout(ObservationLayout::from_blocks(match->layout().observation)),
        players(match->slot_count()),
        obs(players.size(), std::vector<float>(match->obs_size())),
        act(players.size(), std::vector<float>(69)) {
    for (auto& p : players) p.start({sport, settings.mode, core::kControlDt, layout, 69});
  }

  // One tick: each player observes and acts (then `after_act(slot)`, if given, may read obs and
  // the player), and the match steps. The tick's events.
  nlohmann::json tick(const std::function<void(int)>& after_act = {}) {
    for (size_t s = 0; s < players.size(); ++s) {
      match->observe(static_cast<int>(s), obs[s]);
      players[s].act(obs[s], act[s]);
      if (after_act) after_act(static_cast<int>(s));
    }
    std::vector<std::span<const float>> actions(act.begin(), act.end());
    match->step(actions);
    return match->outcome().info.value("events", nlohmann::json::array());
  }

  bool over() const { return match->outcome().match_over; }

  // Whether player `slot`'s legs are in a step begun before this tick's act(): at a point's first
  // tick, a step run on from the point before.
  bool legs_step_run_on(int slot) const {
    const auto& legs = players[slot].legs();
    return legs->stepping() && legs->step_time_s() > 1.5 * core::kControlDt;
  }

  std::unique_ptr<sports::SportMatch> match;
  ObservationLayout layout;
  std::vector<ScriptedRacketPolicy> players;
  std::vector<std::vector<float>> obs, act;
};

}  // namespace olympics::client
