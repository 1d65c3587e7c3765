// The javelin's figures for `olympics-bench athletics`: SMPLOlympics' metric (the mean valid mark
// and the valid rate, here by the official rules: tip first inside the sector, a standing throw
// from 2 m behind the arc, one attempt) per policy on named seeds; and what the air does to a
// thrown javelin: the tip-first rate of the same releases with and without the crossflow load.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace olympics::bench {

nlohmann::json javelin_throws(const std::string& policy, const std::vector<std::uint64_t>& seeds);
// Per seed one release drawn from it: speed 15-30 m/s, angle 25-40 degrees, the javelin's axis
// 5 below to 10 above its path, pitching at -0.5..0.5 rad/s; flown with the air and without.
nlohmann::json javelin_flight(const std::vector<std::uint64_t>& seeds);
void print_javelin_report(const nlohmann::json& report);

}  // namespace olympics::bench
