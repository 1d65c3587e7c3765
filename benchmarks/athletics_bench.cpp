#include "athletics_bench.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include "bench_support.h"
#include "core/humanoid_assets.h"
#include "javelin_bench.h"
#include "hurdles_bench.h"

namespace olympics::bench {
namespace {

// The attempt's decision (the first `mark`/`foul`/`cleared`/`failure` event) of a solo episode.
nlohmann::json decision(const std::string& sport, const nlohmann::json& options, std::uint64_t seed,
                        const std::string& policy) {
  nlohmann::json decided;
  play_in_process(sport, {"solo", seed, 0.0, options}, {policy}, [&](const sports::SportMatch& m) {
    for (const auto& e : m.outcome().info["events"])
      if (decided.is_null() && e["call"] != "fall") decided = e;
  });
  return decided;
}

nlohmann::json long_jumps(const std::string& policy, const std::vector<std::uint64_t>& seeds) {
  int valid = 0, fouls = 0;
  double marks = 0;
  std::map<std::string, int> endings;
  const nlohmann::json options = {{"rules", "official"}, {"attempts", 1}};
  for (const std::uint64_t seed : seeds) {
    const nlohmann::json e = decision("long_jump", options, seed, policy);
    if (e.is_null()) {
      ++endings["undecided"];
    } else if (e["call"] == "mark") {
      ++valid, marks += e["mark"].get<double>(), ++endings["mark"];
    } else {
      ++fouls, ++endings[e["reason"].get<std::string>()];
    }
  }
  const int n = static_cast<int>(seeds.size());
  return {{"attempts", n},
          {"valid_rate", static_cast<double>(valid) / n},
          {"valid_ci95", wilson_95(valid, n)},
          {"foul_rate", static_cast<double>(fouls) / n},
          {"foul_ci95", wilson_95(fouls, n)},
          {"mean_mark_m", valid ? marks / valid : 0.0},
          {"endings", endings}};
}

nlohmann::json high_jumps(const std::string& policy, const std::vector<std::uint64_t>& seeds) {
  nlohmann::json by_height = nlohmann::json::object();
  for (const double height : {0.5, 1.0, 1.5, 2.0}) {
    int cleared = 0;
    std::map<std::string, int> endings;
    for (const std::uint64_t seed : seeds) {
      const nlohmann::json e = decision("high_jump", {{"bar_height", height}}, seed, policy);
      const std::string end = e.is_null()              ? "undecided"
                              : e["call"] == "cleared" ? "cleared"
                                                       : e["reason"].get<std::string>();
      cleared += end == "cleared";
      ++endings[end];
    }
    const int n = static_cast<int>(seeds.size());
    char key[16];
    std::snprintf(key, sizeof key, "%.1f", height);
    by_height[key] = {{"attempts", n},
                      {"leap_over_rate", static_cast<double>(cleared) / n},
                      {"leap_over_ci95", wilson_95(cleared, n)},
                      {"endings", endings}};
  }
  return by_height;
}

}  // namespace

nlohmann::json run_athletics_bench(const AthleticsBenchOptions& o) {
  const auto seeds = episode_seeds(o.seeds, o.episodes);
  nlohmann::json report = {
      {"seeds", o.seeds.empty() ? "1-" + std::to_string(o.episodes) : o.seeds}};
  auto wanted = [&o](const std::string& event) {
    return std::find(o.events.begin(), o.events.end(), event) != o.events.end();
  };
  for (const auto& policy : o.policies) {
    if (wanted("long_jump")) report["long_jump"][policy] = long_jumps(policy, seeds);
    if (wanted("high_jump")) report["high_jump"][policy] = high_jumps(policy, seeds);
    if (wanted("javelin")) report["javelin"][policy] = javelin_throws(policy, seeds);
    if (wanted("hurdles"))
      for (const char* rules : {"paper", "official"})
        report["hurdles"][rules][policy] = hurdles_races(policy, seeds, {{"rules", rules}});
  }
  if (wanted("javelin")) report["javelin_flight"] = javelin_flight(seeds);
  if (o.speed) {
    const core::ModelSpec& smpl = core::load_humanoid(core::HumanoidKind::Smpl);
    for (const char* sport : {"long_jump", "high_jump"})
      if (wanted(sport))
        report["speed_competition_8"][sport] =
            speed_vs_bare(sport, smpl, o.seconds, o.repeats, 45, "competition_8");
    if (wanted("hurdles"))
      report["speed_competition_8"]["hurdles"] = speed_vs_bare(
          "hurdles", smpl, o.seconds, o.repeats, 45, "competition_8", {{"rules", "official"}});
    // The javelin's SMPL-X athletes, over the first 15 ticks (the javelins still held).
    if (wanted("javelin"))
      report["speed_competition_8"]["javelin"] =
          speed_vs_bare("javelin", core::load_humanoid(core::HumanoidKind::SmplX), o.seconds,
                        o.repeats, 15, "competition_8");
  }
  return report;
}

void print_athletics_report(const nlohmann::json& r) {
  std::printf("seeds %s\n", r["seeds"].get<std::string>().c_str());
  static const nlohmann::json kNone = nlohmann::json::object();  // an event not measured
  if (r.contains("long_jump")) std::printf("long jump (official, one attempt):\n");
  for (const auto& [policy, v] : (r.contains("long_jump") ? r["long_jump"] : kNone).items())
    std::printf("  %-8s valid %.2f [%.2f, %.2f]  fouls %.2f [%.2f, %.2f]  mean mark %.2f m  %s\n",
                policy.c_str(), v["valid_rate"].get<double>(), v["valid_ci95"][0].get<double>(),
                v["valid_ci95"][1].get<double>(), v["foul_rate"].get<double>(),
                v["foul_ci95"][0].get<double>(), v["foul_ci95"][1].get<double>(),
                v["mean_mark_m"].get<double>(), v["endings"].dump().c_str());
  if (r.contains("high_jump"))
    std::printf("high jump (paper, one try): leap-over rate per bar height\n");
  for (const auto& [policy, heights] : (r.contains("high_jump") ? r["high_jump"] : kNone).items())
    for (const auto& [h, v] : heights.items())
      std::printf("  %-8s %s m  %.2f [%.2f, %.2f]  %s\n", policy.c_str(), h.c_str(),
                  v["leap_over_rate"].get<double>(), v["leap_over_ci95"][0].get<double>(),
                  v["leap_over_ci95"][1].get<double>(), v["endings"].dump().c_str());
  print_javelin_report(r);
  if (r.contains("hurdles")) print_hurdles_report(r["hurdles"]);
  if (!r.contains("speed_competition_8")) return;
  for (const auto& [sport, v] : r["speed_competition_8"].items())
    std::printf(
        "%s competition_8 ticks/s on one core (zero actions, first %d ticks): match %.0f, bare "
        "physics of 8 humanoids %.0f (ratio %.2f)\n",
        sport.c_str(), v["ticks_per_match"].get<int>(), v["match_ticks_per_s"].get<double>(),
        v["bare_physics_ticks_per_s"].get<double>(), v["ratio"].get<double>());
}

}  // namespace olympics::bench
