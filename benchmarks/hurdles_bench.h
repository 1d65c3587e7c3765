// Hurdles figures for `olympics-bench athletics`: SMPLOlympics' evaluation of the hurdles
// (completion rate, mean time) and the hurdles knocked over, per policy, solo races on named
// seeds, under both rule sets.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace olympics::bench {

// Solo races of `policy` under `options`, one per seed: finishes (a rate with its Wilson 95%
// interval), the finishers' mean time (+- 1.96 standard errors), hurdles knocked, how runs ended.
nlohmann::json hurdles_races(const std::string& policy, const std::vector<std::uint64_t>& seeds,
                             const nlohmann::json& options);
// The report's "hurdles" part: {rules: {policy: races}}.
void print_hurdles_report(const nlohmann::json& by_rules);

}  // namespace olympics::bench
