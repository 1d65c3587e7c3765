// Tennis and table tennis figures: how often the scripted baseline touches the ball in the
// ball-return task, and match ticks/s per core against bare physics (the same equipped humanoids
// stepping with no ball, referee or rewards), measured interleaved.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace olympics::bench {

struct RacketBenchOptions {
  int episodes = 100;  // ball-return episodes per sport and policy
  double seconds = 2;  // wall seconds per speed measurement
  int repeats = 3;     // interleaved repeats (median reported)
  // Ball-return players: any olympics-agent policy (mlp:FILE measures a trained snapshot on
  // seeds 1..episodes, which the trainer never plays: its seeds start at 10^6).
  std::vector<std::string> policies = {"scripted", "zero"};
  std::vector<std::string> sports = {"tennis", "table_tennis"};
  bool speed = true;  // also the 1v1 ticks/s figure
};

nlohmann::json run_racket_bench(const RacketBenchOptions& options);
void print_racket_report(const nlohmann::json& report);

}  // namespace olympics::bench
