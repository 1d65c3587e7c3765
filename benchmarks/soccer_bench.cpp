#include "soccer_bench.h"

#include <cstdio>
#include <map>

#include "bench_support.h"
#include "core/humanoid_assets.h"
#include "registry.h"
#include "soccer/soccer_match.h"

namespace olympics::bench {
namespace {

// Plays one match of soccer with one policy per slot: counts every referee call in `calls` and
// which slots touched the ball in `touched`; returns how it ended and its goals.
nlohmann::json play(const std::string& mode, std::uint64_t seed,
                    const std::vector<std::string>& policies, const nlohmann::json& options,
                    std::map<std::string, int>& calls, std::vector<int>& touched) {
  touched.assign(policies.size(), 0);
  const auto match = play_in_process(
      "soccer", {mode, seed, 0.0, options}, policies, [&](const sports::SportMatch& m) {
        const auto& soccer = dynamic_cast<const sports::soccer::SoccerMatch&>(m);
        for (int s = 0; s < m.slot_count(); ++s) touched[s] |= soccer.touched_this_tick(s);
        for (const auto& e : m.outcome().info["events"]) ++calls[e["call"].get<std::string>()];
      });
  const auto& o = match->outcome();
  return {{"reason", o.reason},
          {"winner_team", o.winner_team},
          {"scores", o.scores},
          {"seconds", match->tick() / 30.0},
          {"goals", o.info.value("goals", nlohmann::json::array())}};
}

// Penalty kicks by `policy`, against a goalkeeper playing `keeper` when it is given.
nlohmann::json penalty_kicks(const std::string& policy, const std::vector<std::uint64_t>& seeds,
                             const std::string& keeper = "") {
  int scored = 0, touched = 0, keeper_touched = 0;
  double seconds_to_goal = 0;
  std::map<std::string, int> calls, endings;
  const int kicks = static_cast<int>(seeds.size());
  for (const std::uint64_t seed : seeds) {
    std::vector<int> touch;
    const auto r = keeper.empty()
                       ? play("penalty_kick", seed, {policy}, {}, calls, touch)
                       : play("penalty_kick_keeper", seed, {policy, keeper}, {}, calls, touch);
    const bool goal = r["reason"] == "goal";
    scored += goal;
    touched += touch[0];
    if (!keeper.empty()) keeper_touched += touch[1];
    if (goal) seconds_to_goal += r["seconds"].get<double>();
    ++endings[r["reason"].get<std::string>()];
  }
  nlohmann::json k = {{"kicks", kicks},
                      {"scored", static_cast<double>(scored) / kicks},
                      {"scored_ci95", wilson_95(scored, kicks)},
                      {"touched", static_cast<double>(touched) / kicks},
                      {"falls", calls["fall"]},
                      {"mean_s_to_goal", scored ? seconds_to_goal / scored : 0.0},
                      {"endings", endings}};
  if (!keeper.empty()) k["keeper_touched"] = static_cast<double>(keeper_touched) / kicks;
  return k;
}

// Scripted-vs-scripted matches; goals per 10 minutes and falls per player-minute with their 95%
// intervals over matches (a match is one episode: its goals and falls are not independent).
nlohmann::json scripted_matches(const std::string& mode, const std::vector<std::uint64_t>& seeds,
                                double half_s) {
  const int n = sports::sport_or_throw("soccer").modes().at(mode).slot_count();
  std::map<std::string, int> calls;
  int goals = 0, assists = 0, own_goals = 0;
  double minutes = 0;
  std::array<int, 2> wins{};
  int draws = 0;
  std::vector<double> match_goals, match_falls, match_minutes, player_minutes;
  for (const std::uint64_t seed : seeds) {
    std::vector<int> touch;
    const int falls_before = calls["fall"];
    const auto r = play(mode, seed, std::vector<std::string>(n, "scripted"),
                        {{"half_s", half_s}, {"falls", "stand_up"}}, calls, touch);
    minutes += r["seconds"].get<double>() / 60;
    match_minutes.push_back(r["seconds"].get<double>() / 60);
    player_minutes.push_back(n * match_minutes.back());
    match_goals.push_back(static_cast<double>(r["goals"].size()));
    match_falls.push_back(calls["fall"] - falls_before);
    for (const auto& g : r["goals"]) {
      ++goals;
      assists += g.value("assist_slot", -1) >= 0;
      own_goals += g.value("own_goal", false);
    }
    const int w = r["winner_team"];
    if (w >= 0)
      ++wins[w];
    else
      ++draws;
  }
  const auto per_minute = ratio_95(match_goals, match_minutes);
  const auto falls = ratio_95(match_falls, player_minutes);
  return {{"matches", static_cast<int>(seeds.size())},
          {"minutes", minutes},
          {"player_minutes", n * minutes},
          {"goals", goals},
          {"goals_per_10_min", 10 * per_minute[0]},
          {"goals_per_10_min_ci95", {10 * per_minute[1], 10 * per_minute[2]}},
          {"falls", calls["fall"]},
          {"falls_per_player_min", falls[0]},
          {"falls_per_player_min_ci95", {falls[1], falls[2]}},
          {"assists", assists},
          {"own_goals", own_goals},
          {"wins", wins},
          {"draws", draws},
          {"calls", calls}};
}

}  // namespace

nlohmann::json run_soccer_bench(const SoccerBenchOptions& o) {
  const std::string named = named_or_evaluation_seeds(o.seeds, o.kicks);
  const std::vector<std::uint64_t> seeds = episode_seeds(named, 0);
  nlohmann::json report = {{"penalty_kick", nlohmann::json::object()}, {"seeds", named}};
  for (const auto& p : o.policies) report["penalty_kick"][p] = penalty_kicks(p, seeds);
  if (o.keeper)
    report["penalty_kick_keeper"]["scripted"] = penalty_kicks("scripted", seeds, "scripted");
  const std::string named_matches = named_or_evaluation_seeds(o.match_seeds, o.matches);
  const std::vector<std::uint64_t> match_seeds = episode_seeds(named_matches, 0);
  report["match_seeds"] = named_matches;
  for (const char* mode : {"1v1", "2v2"})
    report["scripted_" + std::string(mode)] = scripted_matches(mode, match_seeds, o.half_s);
  if (o.speed) {
    static const core::ModelSpec smpl = core::load_humanoid(core::HumanoidKind::Smpl);
    report["speed_2v2"] = speed_vs_bare("soccer", smpl, o.seconds, o.repeats, 45, "2v2");
  }
  return report;
}

void print_soccer_report(const nlohmann::json& r) {
  std::printf("penalty kick seeds %s\n", r["seeds"].get<std::string>().c_str());
  for (const char* mode : {"penalty_kick", "penalty_kick_keeper"}) {
    if (!r.contains(mode)) continue;
    for (const auto& [policy, k] : r[mode].items()) {
      std::printf(
          "%s, %-9s %d kicks: scored %.1f%% (95%% interval %.1f-%.1f%%), touched %.0f%%, "
          "falls %d, %.1f s to a goal; endings %s\n",
          std::string(mode) == "penalty_kick" ? "penalty kick" : "penalty kick v scripted keeper",
          policy.c_str(), k["kicks"].get<int>(), 100 * k["scored"].get<double>(),
          100 * k["scored_ci95"][0].get<double>(), 100 * k["scored_ci95"][1].get<double>(),
          100 * k["touched"].get<double>(), k["falls"].get<int>(),
          k["mean_s_to_goal"].get<double>(), k["endings"].dump().c_str());
    }
  }
  std::printf("match seeds %s\n", r["match_seeds"].get<std::string>().c_str());
  for (const char* mode : {"1v1", "2v2"}) {
    const auto& m = r["scripted_" + std::string(mode)];
    std::printf(
        "scripted %s, %d matches, %.1f min: %d goals (%.1f per 10 min, 95%% interval %.1f-%.1f), "
        "%d falls (%.2f per player-minute, %.2f-%.2f), assists %d, own goals %d, wins %d-%d, "
        "draws %d\n  calls %s\n",
        mode, m["matches"].get<int>(), m["minutes"].get<double>(), m["goals"].get<int>(),
        m["goals_per_10_min"].get<double>(), m["goals_per_10_min_ci95"][0].get<double>(),
        m["goals_per_10_min_ci95"][1].get<double>(), m["falls"].get<int>(),
        m["falls_per_player_min"].get<double>(), m["falls_per_player_min_ci95"][0].get<double>(),
        m["falls_per_player_min_ci95"][1].get<double>(), m["assists"].get<int>(),
        m["own_goals"].get<int>(), m["wins"][0].get<int>(), m["wins"][1].get<int>(),
        m["draws"].get<int>(), m["calls"].dump().c_str());
  }
  if (!r.contains("speed_2v2")) return;
  const auto& v = r["speed_2v2"];
  std::printf(
      "2v2 ticks/s on one core (zero actions, first %d ticks): match %.0f, bare physics of "
      "four humanoids %.0f, ratio %.2f\n",
      v["ticks_per_match"].get<int>(), v["match_ticks_per_s"].get<double>(),
      v["bare_physics_ticks_per_s"].get<double>(), v["ratio"].get<double>());
}

}  // namespace olympics::bench
