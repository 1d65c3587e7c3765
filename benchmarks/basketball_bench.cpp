#include "basketball_bench.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include "bench_support.h"
#include "core/humanoid_assets.h"

namespace olympics::bench {
namespace {

nlohmann::json free_throws(const std::string& policy, const std::vector<std::uint64_t>& seeds,
                           const nlohmann::json& options = nlohmann::json::object()) {
  int made = 0;
  std::map<std::string, int> endings;
  for (const std::uint64_t seed : seeds) {
    const auto match = play_in_process("basketball", {"free_throw", seed, 0.0, options}, {policy});
    made += match->outcome().reason == "basket";
    ++endings[match->outcome().reason];
  }
  const int throws = static_cast<int>(seeds.size());
  return {{"throws", throws},
          {"made", static_cast<double>(made) / throws},
          {"made_ci95", wilson_95(made, throws)},
          {"endings", endings}};
}

}  // namespace

nlohmann::json run_basketball_bench(const BasketballBenchOptions& o) {
  const std::vector<std::uint64_t> seeds = episode_seeds(o.seeds, o.throws);
  nlohmann::json report = {{"free_throw", nlohmann::json::object()},
                           {"seeds", o.seeds.empty() ? "1-" + std::to_string(o.throws) : o.seeds}};
  for (const auto& p : o.policies) report["free_throw"][p] = free_throws(p, seeds);
  // The scripted shooter aims by the ballistic solution: from nearer lines too.
  const bool scripted =
      std::find(o.policies.begin(), o.policies.end(), "scripted") != o.policies.end();
  for (double d : scripted ? o.scripted_distances : std::vector<double>{}) {
    char key[32];
    std::snprintf(key, sizeof key, "%g", d);
    report["scripted_by_distance"][key] =
        free_throws("scripted", seeds, {{"free_throw_distance", d}});
  }
  if (o.speed) {
    static const core::ModelSpec smplx = core::load_humanoid(core::HumanoidKind::SmplX);
    for (const char* mode : {"1v1", "2v2"})
      report["speed_" + std::string(mode)] =
          speed_vs_bare("basketball", smplx, o.seconds, o.repeats, 45, mode);
  }
  return report;
}

void print_basketball_report(const nlohmann::json& r) {
  std::printf("seeds %s\n", r["seeds"].get<std::string>().c_str());
  for (const auto& [policy, f] : r["free_throw"].items())
    std::printf("free throw, %-9s %d throws: made %.1f%% (95%% interval %.1f-%.1f%%); endings %s\n",
                policy.c_str(), f["throws"].get<int>(), 100 * f["made"].get<double>(),
                100 * f["made_ci95"][0].get<double>(), 100 * f["made_ci95"][1].get<double>(),
                f["endings"].dump().c_str());
  if (r.contains("scripted_by_distance"))
    for (const auto& [d, f] : r["scripted_by_distance"].items())
      std::printf(
          "free throw, scripted from %s m (the rule's line: 4.6 m), %d throws: made %.1f%% (95%% "
          "interval %.1f-%.1f%%)\n",
          d.c_str(), f["throws"].get<int>(), 100 * f["made"].get<double>(),
          100 * f["made_ci95"][0].get<double>(), 100 * f["made_ci95"][1].get<double>());
  for (const char* mode : {"1v1", "2v2"}) {
    const std::string key = "speed_" + std::string(mode);
    if (!r.contains(key)) continue;
    const auto& v = r[key];
    std::printf(
        "%s ticks/s on one core (zero actions, first %d ticks): match %.0f, bare physics of as "
        "many SMPL-X humanoids %.0f, ratio %.2f\n",
        mode, v["ticks_per_match"].get<int>(), v["match_ticks_per_s"].get<double>(),
        v["bare_physics_ticks_per_s"].get<double>(), v["ratio"].get<double>());
  }
}

}  // namespace olympics::bench
