// Hurdles figures for `olympics-bench athletics`: SMPLOlympics' evaluation of the hurdles
// (completion rate, mean time) and the hurdles knocked over, per policy, solo races on named
// seeds, under the seed's rules, the official 110 m and the official (women's) 100 m.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace olympics::bench {

// The rule sets the hurdles are measured under, by report name: "paper" (the seed's walls),
// "official" (110 m, 1.067 m hurdles that tip over) and "official_100m" (the women's race: 100 m,
// 0.838 m hurdles, 13.00 m to the first, 8.50 m between).
std::vector<std::pair<std::string, nlohmann::json>> hurdles_rule_sets();

// Solo races of `policy` under `options`, one per seed: finishes (a rate with its Wilson 95%
// interval), the finishers' mean time (+- 1.96 standard errors), hurdles knocked, how runs ended.
nlohmann::json hurdles_races(const std::string& policy, const std::vector<std::uint64_t>& seeds,
                             const nlohmann::json& options);
// The report's "hurdles" part: {rules: {policy: races}}.
void print_hurdles_report(const nlohmann::json& by_rules);

}  // namespace olympics::bench
