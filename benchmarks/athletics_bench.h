// Athletics figures, SMPLOlympics' evaluation metrics per event, for the zero, random and
// scripted policies on named seeds (by default the project's evaluation seeds from 5001 on, which
// no scripted athlete was tuned on): the long jump's valid-mark and foul rates and mean mark
// (official rules, one attempt each, from the runway's start and as a standing jump); the high
// jump's leap-over rate per bar height (the seed's 0.5, 1.0, 1.5, 2.0 m, paper rules) and the
// official first try at 0.5 and 1.0 m; the javelin's valid rate and mark; the hurdles' completion
// rate, mean time and hurdles knocked (hurdles_bench.h); golf's hit and holed rates; and the
// ticks/s of an 8-athlete competition of each against the bare physics of 8 humanoids.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace olympics::bench {

struct AthleticsBenchOptions {
  // Per policy and event, the evaluation seeds from 5001 (kFirstEvaluationSeed) when `seeds` is
  // empty.
  int episodes = 50;
  std::string seeds;  // or the seeds named: "9001-9050" (docs/figures.md)
  std::vector<std::string> policies = {"zero", "random", "scripted"};
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
