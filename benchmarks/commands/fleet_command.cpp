// olympics-bench fleet [--json] [--db URL] [--fixtures N] [--cells C] [--batch B]
#include "bench_command.h"
#include "fleet_bench.h"

namespace olympics::bench {

BenchCommand fleet_command(CLI::App& app) {
  BenchCommand c(app, "fleet", "the fleet's PostgreSQL fixture queue: fixtures/s, lease latency");
  auto o = std::make_shared<FleetBenchOptions>();
  c.cli().add_option("--db", o->db, "postgresql:// URL (default $OLYMPICS_TEST_POSTGRES_URL)");
  c.cli().add_option("--fixtures", o->fixtures, "fixtures queued")->check(CLI::PositiveNumber);
  c.cli().add_option("--cells", o->cells, "cells leasing at once")->check(CLI::PositiveNumber);
  c.cli().add_option("--batch", o->batch, "fixtures per lease")->check(CLI::PositiveNumber);
  c.measure = [o] { return run_fleet_bench(*o); };
  c.print = print_fleet_report;
  return c;
}

}  // namespace olympics::bench
