// `olympics-bench physics`: our physics against MuJoCo on the same humanoid files.
#pragma once

#include <nlohmann/json.hpp>

namespace olympics::bench {

struct PhysicsBenchOptions {
  double seconds = 1.5;  // wall time per measurement
  int repeats = 3;       // interleaved repeats; the median is reported
  int max_threads = 0;   // thread-scaling sweep up to this many threads (0: all cores)
  bool with_mujoco = true;
};

nlohmann::json run_physics_bench(const PhysicsBenchOptions& options);
void print_physics_report(const nlohmann::json& report);

}  // namespace olympics::bench
