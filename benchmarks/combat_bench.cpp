#include "combat_bench.h"

#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <thread>

#include "bench_support.h"
#include "boxing/boxing_match.h"
#include "fencing/fencing_match.h"
#include "policies.h"
#include "registry.h"

namespace olympics::bench {
namespace {

// One bout as it ended; per-side counts are [slot 0, slot 1].
struct Bout {
  double minutes = 0;
  std::array<int, 2> scored{};    // touches by the tip (fencing) / scoring punches (boxing)
  std::array<int, 2> hits{};      // fencing: hits on target above the threshold
  std::array<int, 2> by_falls{};  // fencing: touches given by the other's fall
  std::array<int, 2> knockdowns{}, falls{};
  int halts = 0, knockouts = 0;
  int winner = -1;     // -1: a draw
  std::string ending;  // the match's reason: bout_won, time_limit, knockout, decision, ...
};

// What the bouts of one pairing added up to, in seed order.
struct BoutStats {
  std::vector<Bout> bouts;
  double minutes() const {
    double m = 0;
    for (const Bout& b : bouts) m += b.minutes;
    return m;
  }
};

Bout play_bout(const sports::Sport& s, const std::string& sport, const std::string& p0,
               const std::string& p1, std::uint64_t seed) {
  auto match = s.create({"1v1", seed, 0.0, {}});
  std::array<std::unique_ptr<client::Policy>, 2> policies = {client::make_policy(p0, 2 * seed),
                                                             client::make_policy(p1, 2 * seed + 1)};
  for (auto& p : policies) p->start(in_process_match_info(sport, "1v1", *match));
  std::vector<std::vector<float>> obs(2, std::vector<float>(match->obs_size())),
      act(2, std::vector<float>(match->action_size()));
  Bout st;
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
  st.minutes = match->tick() / 30.0 / 60.0;
  st.winner = match->outcome().winner_team;
  st.ending = match->outcome().reason;
  return st;
}

// The bouts of one pairing on `threads` threads (each bout is its own world; the results are
// gathered in seed order, so the figures do not depend on the thread count).
BoutStats play_bouts(const std::string& sport, const std::string& p0, const std::string& p1,
                     const std::vector<std::uint64_t>& seeds, int threads) {
  const auto& s = sports::sport_or_throw(sport);
  BoutStats st;
  st.bouts.resize(seeds.size());
  std::atomic<size_t> next{0};
  std::vector<std::thread> pool;
  for (int t = 0; t < std::max(1, threads); ++t)
    pool.emplace_back([&] {
      for (size_t k = next++; k < seeds.size(); k = next++)
        st.bouts[k] = play_bout(s, sport, p0, p1, seeds[k]);
    });
  for (auto& th : pool) th.join();
  return st;
}

// A rate per minute over bouts (bouts differ in length): bench_support's ratio estimator.
nlohmann::json per_minute(const std::vector<double>& counts, const std::vector<double>& minutes) {
  const auto [rate, low, high] = ratio_95(counts, minutes);
  return {{"per_min", rate}, {"ci95", {low, high}}};
}

nlohmann::json to_json(const BoutStats& st, const std::string& sport) {
  const bool fencing = sport == "fencing";
  auto sum = [&](auto field) {
    std::array<int, 2> t{};
    for (const Bout& b : st.bouts)
      for (int i = 0; i < 2; ++i) t[i] += (b.*field)[i];
    return t;
  };
  const int n = static_cast<int>(st.bouts.size());
  std::array<int, 2> wins{};
  int draws = 0, halts = 0, knockouts = 0, by_points = 0;
  std::map<std::string, int> endings;
  std::vector<double> scored, falls, minutes;
  for (const Bout& b : st.bouts) {
    if (b.winner >= 0)
      ++wins[b.winner];
    else
      ++draws;
    halts += b.halts;
    knockouts += b.knockouts;
    ++endings[b.ending];
    // Decided on the score: fencing, won on touches (at the touches or leading at the time
    // limit; by default a fall gives no touch); boxing, on the cards (a decision or a decision
    // draw), not by a knock-out.
    by_points += fencing ? b.winner >= 0 && b.by_falls[0] + b.by_falls[1] == 0
                         : b.ending == "decision" || b.ending == "decision_draw";
    scored.push_back(b.scored[0] + b.scored[1]);
    falls.push_back(b.falls[0] + b.falls[1]);
    minutes.push_back(b.minutes);
  }
  const std::string scored_name = fencing ? "touches" : "scoring_punches";
  const nlohmann::json scored_rate = per_minute(scored, minutes);
  nlohmann::json j = {
      {"bouts", n},
      {"bout_minutes", st.minutes()},
      {scored_name, sum(&Bout::scored)},
      {fencing ? "touches_per_min" : "punches_per_min", scored_rate["per_min"]},
      {fencing ? "touches_per_min_ci95" : "punches_per_min_ci95", scored_rate["ci95"]},
      {"falls", sum(&Bout::falls)},
      {"falls_per_min", per_minute(falls, minutes)["per_min"]},
      {"falls_per_min_ci95", per_minute(falls, minutes)["ci95"]},
      {"endings", endings},
      {fencing ? "decided_by_touches" : "decided_by_points", n > 0 ? double(by_points) / n : 0},
      {fencing ? "decided_by_touches_ci95" : "decided_by_points_ci95", wilson_95(by_points, n)},
      {"wins", wins},
      {"wins_0_ci95", wilson_95(wins[0], n)},  // slot 0's share of bouts won
      {"draws", draws}};
  if (fencing) {
    j["hits"] = sum(&Bout::hits);
    j["touches_by_falls"] = sum(&Bout::by_falls);
    j["halts"] = halts;
  } else {
    j["knockdowns"] = sum(&Bout::knockdowns);
    j["knockouts"] = knockouts;
  }
  return j;
}

}  // namespace

nlohmann::json run_combat_bench(const CombatBenchOptions& o) {
  const std::string named = named_or_evaluation_seeds(o.seeds, o.bouts);
  const std::vector<std::uint64_t> seeds = episode_seeds(named, 0);
  nlohmann::json report = {{"bouts", static_cast<int>(seeds.size())},
                           {"seeds", named},
                           {"sports", nlohmann::json::object()}};
  std::vector<std::array<std::string, 2>> pairings = {
      {"scripted", "scripted"}, {"scripted", "zero"}, {"random", "random"}};
  if (!o.challenger.empty()) pairings = {{"scripted", "scripted"}, {o.challenger, "scripted"}};
  if (!o.pairings.empty()) {
    pairings.clear();
    for (const std::string& p : o.pairings) {
      const size_t vs = p.find("_vs_");
      if (vs == std::string::npos || vs == 0 || vs + 4 >= p.size())
        throw std::invalid_argument(
            "--pairings: '" + p + "' is not A_vs_B (e.g. scripted_vs_scripted, scripted_vs_zero)");
      pairings.push_back({p.substr(0, vs), p.substr(vs + 4)});
    }
  }
  for (const std::string& sport : o.sports) {
    nlohmann::json& r = report["sports"][sport];
    for (const auto& [a, b] : pairings)
      r["bouts"][a + "_vs_" + b] = to_json(play_bouts(sport, a, b, seeds, o.threads), sport);
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
      const char* decided = fencing ? "decided_by_touches" : "decided_by_points";
      std::printf(
          "\n    per min: %s %.2f (95%% %.2f-%.2f), falls %.2f (95%% %.2f-%.2f); decided by %s "
          "%.0f%% (95%% %.0f-%.0f%%); endings %s\n   ",
          fencing ? "touches" : "punches",
          s[fencing ? "touches_per_min" : "punches_per_min"].get<double>(),
          s[fencing ? "touches_per_min_ci95" : "punches_per_min_ci95"][0].get<double>(),
          s[fencing ? "touches_per_min_ci95" : "punches_per_min_ci95"][1].get<double>(),
          s["falls_per_min"].get<double>(), s["falls_per_min_ci95"][0].get<double>(),
          s["falls_per_min_ci95"][1].get<double>(), fencing ? "touches" : "points",
          100 * s[decided].get<double>(), 100 * s[std::string(decided) + "_ci95"][0].get<double>(),
          100 * s[std::string(decided) + "_ci95"][1].get<double>(), s["endings"].dump().c_str());
      std::printf(" falls %d-%d, wins %d-%d (slot 0: 95%% interval %.0f-%.0f%%), draws %d\n",
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
