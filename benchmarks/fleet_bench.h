// The fleet's fixture queue alone (docs/deploy.md): N fixtures queued in PostgreSQL, C cells
// (threads, a connection each) leasing batches and storing each result at once, no matches
// played; fixtures per second through the queue and the latency of a lease and of a stored result.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace olympics::bench {

struct FleetBenchOptions {
  std::string db;  // "" = $OLYMPICS_TEST_POSTGRES_URL
  int fixtures = 1000;
  int cells = 3;
  int batch = 1;
};

nlohmann::json run_fleet_bench(const FleetBenchOptions& options);
void print_fleet_report(const nlohmann::json& report);

}  // namespace olympics::bench
