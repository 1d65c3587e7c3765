// `olympics-bench server`: match ticks/s of a real server over LCM against bare physics.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace olympics::bench {

struct ServerBenchOptions {
  double seconds = 3.0;           // wall time per measurement
  int matches = 8;                // concurrent matches, one client each (both slots)
  int workers = 1;                // server threads: 1 = "per core"
  bool pin = true;                // workers alone on their cores, everything else on the others
  bool signed_messages = false;   // a deployment secret: every message signed and checked
  std::string provider = "udpm";  // LCM provider: udpm (one port) or mpudpm (channels on ports)
  int live_viewers = 0;           // HTTP clients watching matches live (serve --view-port)
  // One vector client plays every match (its traffic in bundles, docs/protocol.md) instead of
  // one client per match.
  bool vector_client = false;
  int async_batch = 0;  // with vector_client: async, each recv taking this many ready matches
};

nlohmann::json run_server_bench(const ServerBenchOptions& options);
void print_server_report(const nlohmann::json& report);

}  // namespace olympics::bench
