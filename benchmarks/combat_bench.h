// Fencing and boxing figures, the yardsticks learned fighters must beat: over bouts with fixed
// seeds (1..N), for scripted vs scripted, scripted vs zero and random vs random, the touches
// (fencing) and scoring punches (boxing) per minute of bout, knock-downs, falls and how bouts
// end; and 1v1 ticks/s per core against the bare physics of the same equipped humanoids,
// measured interleaved.
#pragma once

#include <nlohmann/json.hpp>

namespace olympics::bench {

struct CombatBenchOptions {
  int bouts = 100;     // per sport and pairing
  double seconds = 2;  // wall seconds per speed measurement
  int repeats = 3;     // interleaved repeats (median reported)
};

nlohmann::json run_combat_bench(const CombatBenchOptions& options);
void print_combat_report(const nlohmann::json& report);

}  // namespace olympics::bench
