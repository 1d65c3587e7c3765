// Tennis and table tennis figures: how often the scripted baseline touches the ball in the
// ball-return task, and match ticks/s per core against bare physics (the same equipped humanoids
// stepping with no ball, referee or rewards), measured interleaved.
#pragma once

#include <nlohmann/json.hpp>

namespace olympics::bench {

struct RacketBenchOptions {
  int episodes = 100;  // ball-return episodes per sport and policy
  double seconds = 2;  // wall seconds per speed measurement
  int repeats = 3;     // interleaved repeats (median reported)
};

nlohmann::json run_racket_bench(const RacketBenchOptions& options);
void print_racket_report(const nlohmann::json& report);

}  // namespace olympics::bench
