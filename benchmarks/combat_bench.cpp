#include "combat_bench.h"

#include <array>
#include <cstdio>

#include "bench_support.h"
#include "boxing/boxing_match.h"
#include "fencing/fencing_match.h"
#include "policies.h"
#include "registry.h"

namespace olympics::bench {
namespace {

// What the bouts of one pairing added up to; per-side counts are [slot 0, slot 1].
struct BoutStats {
  int bouts = 0;
  double minutes = 0;             // of bout time, all bouts together
  std::array<int, 2> scored{};    // touches by the tip (fencing) / scoring punches (boxing)
  std::array<int, 2> hits{};      // fencing: hits on target above the threshold
  std::array<int, 2> by_falls{};  // fencing: touches given by the other's fall
  std::array<int, 2> knockdowns{}, falls{}, wins{};
  int draws = 0, halts = 0, knockouts = 0;
};

BoutStats play_bouts(const std::string& sport, const std::string& p0, const std::string& p1,
                     const std::vector<std::uint64_t>& seeds) {
  const auto& s = sports::sport_or_throw(sport);
  BoutStats st;
  for (const std::uint64_t b : seeds) {
    auto match = s.create({"1v1", b, 0.0, {}});
    std::array<std::unique_ptr<client::Policy>, 2> policies = {client::make_policy(p0, 2 * b),
                                                               client::make_policy(p1, 2 * b + 1)};
    for (auto& p : policies) p->start(in_process_match_info(sport, "1v1", *match));
    std::vector<std::vector<float>> obs(2, std::vector<float>(match->obs_size())),
        act(2, std::vector<float>(match->action_size()));
    while (!match->outcome().match_over) {
      for (int i = 0; i < 2; ++i) {
        match->observe(i, obs[i]);
        policies[i]->act(obs[i], act[i]);
      }
      match->step({act[0], act[1]});
      for (const auto& e : match->outcome().info["events"]) {
        const std::string call = e["call"];
        const int slot = e.value("slot", -1);
        if (call == "fall") ++st.falls[slot];
        if (call == "hit") ++st.hits[slot];
        if (call == "punch") ++st.scored[slot];
        if (call == "knockdown") ++st.knockdowns[slot];
        if (call == "knockout") ++st.knockouts;
        if (call == "halt") ++st.halts;
        if (call == "point") ++(e["reason"] == "fall" ? st.by_falls : st.scored)[slot];
      }
    }
    const auto& o = match->outcome();
    ++st.bouts;
    st.minutes += match->tick() / 30.0 / 60.0;
    if (o.winner_team >= 0)
      ++st.wins[o.winner_team];
    else
      ++st.draws;
  }
  return st;
}

nlohmann::json to_json(const BoutStats& s, const std::string& sport) {
  const bool fencing = sport == "fencing";
  nlohmann::json j = {
      {"bouts", s.bouts},
      {"bout_minutes", s.minutes},
      {fencing ? "touches" : "scoring_punches", s.scored},
      {fencing ? "touches_per_min" : "punches_per_min", (s.scored[0] + s.scored[1]) / s.minutes},
      {"falls", s.falls},
      {"wins", s.wins},
      {"wins_0_ci95", wilson_95(s.wins[0], s.bouts)},  // slot 0's share of bouts won
      {"draws", s.draws}};
  if (fencing) {
    j["hits"] = s.hits;
    j["touches_by_falls"] = s.by_falls;
    j["halts"] = s.halts;
  } else {
    j["knockdowns"] = s.knockdowns;
    j["knockouts"] = s.knockouts;
  }
  return j;
}

}  // namespace

nlohmann::json run_combat_bench(const CombatBenchOptions& o) {
  const std::vector<std::uint64_t> seeds = episode_seeds(o.seeds, o.bouts);
  nlohmann::json report = {{"bouts", static_cast<int>(seeds.size())},
                           {"seeds", o.seeds.empty() ? "1-" + std::to_string(o.bouts) : o.seeds},
                           {"sports", nlohmann::json::object()}};
  std::vector<std::array<std::string, 2>> pairings = {
      {"scripted", "scripted"}, {"scripted", "zero"}, {"random", "random"}};
  if (!o.challenger.empty()) pairings = {{"scripted", "scripted"}, {o.challenger, "scripted"}};
  for (const std::string& sport : o.sports) {
    nlohmann::json& r = report["sports"][sport];
    for (const auto& [a, b] : pairings)
      r["bouts"][a + "_vs_" + b] = to_json(play_bouts(sport, a, b, seeds), sport);
    if (!o.speed) continue;
    const core::ModelSpec& players =
        sport == "fencing" ? sports::fencing::fencer_model() : sports::boxing::boxer_model(true);
    r["speed_1v1"] = speed_vs_bare(sport, players, o.seconds, o.repeats, /*ticks=*/45);
  }
  return report;
}

void print_combat_report(const nlohmann::json& report) {
  for (const auto& [sport, r] : report["sports"].items()) {
    const bool fencing = sport == "fencing";
    std::printf("%s, %d bouts per pairing (seeds %s)\n", sport.c_str(), report["bouts"].get<int>(),
                report["seeds"].get<std::string>().c_str());
    for (const auto& [pairing, s] : r["bouts"].items()) {
      const auto& scored = s[fencing ? "touches" : "scoring_punches"];
      std::printf("  %-20s %6.1f min: %s %d-%d (%.1f/min)", pairing.c_str(),
                  s["bout_minutes"].get<double>(), fencing ? "touches" : "punches",
                  scored[0].get<int>(), scored[1].get<int>(),
                  s[fencing ? "touches_per_min" : "punches_per_min"].get<double>());
      if (fencing)
        std::printf(", hits %d-%d, touches by falls %d-%d, halts %d", s["hits"][0].get<int>(),
                    s["hits"][1].get<int>(), s["touches_by_falls"][0].get<int>(),
                    s["touches_by_falls"][1].get<int>(), s["halts"].get<int>());
      else
        std::printf(", knock-downs %d-%d, knock-outs %d", s["knockdowns"][0].get<int>(),
                    s["knockdowns"][1].get<int>(), s["knockouts"].get<int>());
      std::printf(", falls %d-%d, wins %d-%d (slot 0: 95%% interval %.0f-%.0f%%), draws %d\n",
                  s["falls"][0].get<int>(), s["falls"][1].get<int>(), s["wins"][0].get<int>(),
                  s["wins"][1].get<int>(), 100 * s["wins_0_ci95"][0].get<double>(),
                  100 * s["wins_0_ci95"][1].get<double>(), s["draws"].get<int>());
    }
    if (!r.contains("speed_1v1")) continue;
    const auto& v = r["speed_1v1"];
    std::printf(
        "  1v1 ticks/s on one core (zero actions, the first %d ticks of each bout): match "
        "%.0f, bare physics %.0f, ratio %.2f\n",
        v["ticks_per_match"].get<int>(), v["match_ticks_per_s"].get<double>(),
        v["bare_physics_ticks_per_s"].get<double>(), v["ratio"].get<double>());
  }
}

}  // namespace olympics::bench
