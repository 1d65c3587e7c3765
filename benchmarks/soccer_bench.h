// Soccer figures, the yardsticks learned players must beat: penalty kicks with fixed seeds
// (by default the evaluation seeds from 5001) for scripted, zero and random (fraction scored,
// fraction that touched the ball, falls, how they ended), and the scripted kicker against the
// scripted goalkeeper; goals per 10 minutes and falls per player-minute (95% intervals over
// matches) of scripted-vs-scripted 1v1 and 2v2 matches (with scorers, assists, own goals,
// restarts); and 2v2 ticks/s (four humanoids and the ball) against the bare physics of four
// humanoids, measured interleaved.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace olympics::bench {

struct SoccerBenchOptions {
  int kicks =
      100;  // penalty kicks per policy (evaluation seeds 5001..5000+N) when `seeds` is empty
  std::string seeds;        // or the seeds named: "5001-5500" (docs/figures.md)
  int matches = 3;          // scripted matches per team mode (evaluation seeds 5001..5000+N)...
  std::string match_seeds;  // ...or the seeds named
  double half_s = 120;      // of each match (two halves)
  std::vector<std::string> policies = {"scripted", "zero", "random"};
  double seconds = 2;  // wall seconds per speed measurement
  int repeats = 3;
  bool speed = true;
  bool keeper = true;  // scripted kicks against the scripted goalkeeper (penalty_kick_keeper)
};

nlohmann::json run_soccer_bench(const SoccerBenchOptions& options);
void print_soccer_report(const nlohmann::json& report);

}  // namespace olympics::bench
