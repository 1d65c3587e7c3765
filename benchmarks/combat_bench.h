// Fencing and boxing figures, the yardsticks learned fighters must beat: over bouts with fixed
// seeds (by default the evaluation seeds from 5001), for scripted vs scripted, scripted vs zero and
// random vs random, the touches (fencing) and scoring punches (boxing) per minute of bout,
// knock-downs, falls and how bouts end; and 1v1 ticks/s per core against the bare physics of the
// same equipped humanoids, measured interleaved.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace olympics::bench {

struct CombatBenchOptions {
  int bouts = 100;    // per sport and pairing (evaluation seeds 5001..5000+N) when `seeds` is empty
  std::string seeds;  // or the seeds named: "5001-5500" (docs/figures.md)
  double seconds = 2;  // wall seconds per speed measurement
  int repeats = 3;     // interleaved repeats (median reported)
  // A policy to measure (mlp:FILE: a trained snapshot) in slot 0 against the scripted baseline,
  // on the same seeds (the trainer's start at 10^6).
  std::string challenger;
  std::vector<std::string> sports = {"fencing", "boxing"};
  bool speed = true;  // also the 1v1 ticks/s figure
  // Only these pairings ("scripted_vs_scripted", ...); empty: the three above.
  std::vector<std::string> pairings;
  int threads = 1;  // bouts played at once (the figures do not depend on it)
};

nlohmann::json run_combat_bench(const CombatBenchOptions& options);
void print_combat_report(const nlohmann::json& report);

}  // namespace olympics::bench
