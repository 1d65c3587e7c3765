// `olympics-bench vector`: agent-steps/s of one VectorClient playing many matches on a server,
// against bare physics stepping the same scene on every core.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace olympics::bench {

struct VectorBenchOptions {
  int envs = 16;        // matches the one client plays at once (both slots of each)
  int workers = 0;      // server worker threads of the in-process server; 0 = one per core
  double seconds = 6;   // wall time per measurement
  std::string connect;  // an LCM URL: play on the server there instead of one in process
  // 0: sync step() of every match; k > 0: async (EnvPool's send/recv), each recv taking the
  // first k matches whose observation is in and sending their actions at once.
  int async_batch = 0;
};

nlohmann::json run_vector_bench(const VectorBenchOptions& options);
void print_vector_report(const nlohmann::json& report);

}  // namespace olympics::bench
