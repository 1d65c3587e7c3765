// Athletics figures (SMPLOlympics' evaluation metrics for the two jumps built so far) for the
// policies that exist for them (zero, random: no scripted jumper yet), on named seeds: the long
// jump's valid-mark and foul rates and mean mark (official rules, one attempt each); the high
// jump's leap-over rate per bar height (the seed's 0.5, 1.0, 1.5, 2.0 m, paper rules); the
// hurdles' completion rate, mean time and hurdles knocked (both rule sets, hurdles_bench.h); and
// the ticks/s of an 8-athlete competition of each against the bare physics of 8 humanoids.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace olympics::bench {

struct AthleticsBenchOptions {
  int episodes = 50;  // per policy and event (seeds 1..N) when `seeds` is empty
  std::string seeds;  // or the seeds named: "9001-9050" (docs/figures.md)
  std::vector<std::string> policies = {"zero", "random"};
  std::vector<std::string> events = {
      "long_jump", "standing_long_jump", "high_jump", "high_jump_official", "javelin", "hurdles",
      "golf"};
  double seconds = 2;  // wall seconds per speed measurement
  int repeats = 3;
  bool speed = true;
  // Golf's `address` setting: "placed" (at address for every stroke) or "walk" (for the first
  // only: the policy walks to its ball).
  std::string golf_address = "placed";
};

nlohmann::json run_athletics_bench(const AthleticsBenchOptions& options);
void print_athletics_report(const nlohmann::json& report);

}  // namespace olympics::bench
