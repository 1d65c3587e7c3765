#include "hurdles_bench.h"

#include <cmath>
#include <cstdio>
#include <map>

#include "bench_support.h"

namespace olympics::bench {

std::vector<std::pair<std::string, nlohmann::json>> hurdles_rule_sets() {
  return {{"paper", {{"rules", "paper"}}},
          {"official", {{"rules", "official"}}},
          {"official_100m", {{"rules", "official"}, {"race", "100m"}}}};
}

nlohmann::json hurdles_races(const std::string& policy, const std::vector<std::uint64_t>& seeds,
                             const nlohmann::json& options) {
  int finished = 0;
  double time_sum = 0, time_sq = 0, knocked_finishers = 0, knocked_all = 0;
  std::map<std::string, int> endings;
  for (const std::uint64_t seed : seeds) {
    const auto match = play_in_process("hurdles", {"solo", seed, 0.0, options}, {policy});
    const nlohmann::json& info = match->outcome().info;
    const std::string end = info.at("results").at(0);
    const int knocked = info.at("knocked").at(0);
    ++endings[end];
    knocked_all += knocked;
    if (end != "finished") continue;
    const double t = match->outcome().scores.at(0);
    ++finished, time_sum += t, time_sq += t * t, knocked_finishers += knocked;
  }
  const int n = static_cast<int>(seeds.size());
  const double mean = finished ? time_sum / finished : 0.0;
  const double sd =
      finished > 1 ? std::sqrt((time_sq - finished * mean * mean) / (finished - 1)) : 0.0;
  return {{"races", n},
          {"completion_rate", static_cast<double>(finished) / n},
          {"completion_ci95", wilson_95(finished, n)},
          {"mean_time_s", mean},
          {"mean_time_ci95_s", finished ? 1.96 * sd / std::sqrt(finished) : 0.0},
          {"knocked_per_finish", finished ? knocked_finishers / finished : 0.0},
          {"knocked_per_race", knocked_all / n},
          {"endings", endings}};
}

void print_hurdles_report(const nlohmann::json& by_rules) {
  for (const auto& [rules, policies] : by_rules.items()) {
    std::printf("hurdles (%s rules, solo): completion, mean time of finishers, hurdles knocked\n",
                rules.c_str());
    for (const auto& [policy, v] : policies.items())
      std::printf(
          "  %-8s completed %d of %d = %.2f [%.2f, %.2f]  mean time %.2f +- %.2f s  knocked %.2f "
          "per finish (%.2f per race)  %s\n",
          policy.c_str(),
          static_cast<int>(std::lround(v["completion_rate"].get<double>() * v["races"].get<int>())),
          v["races"].get<int>(), v["completion_rate"].get<double>(),
          v["completion_ci95"][0].get<double>(), v["completion_ci95"][1].get<double>(),
          v["mean_time_s"].get<double>(), v["mean_time_ci95_s"].get<double>(),
          v["knocked_per_finish"].get<double>(), v["knocked_per_race"].get<double>(),
          v["endings"].dump().c_str());
  }
}

}  // namespace olympics::bench
