// olympics-bench vector [--json] [--envs N] [--workers W] [--seconds S] [--async K]
//                       [--connect URL]
#include "bench_command.h"
#include "vector_bench.h"

namespace olympics::bench {

BenchCommand vector_command(CLI::App& app) {
  BenchCommand c(app, "vector",
                 "one vector client's agent-steps/s over LCM vs bare physics on every core");
  auto o = std::make_shared<VectorBenchOptions>();
  auto& cli = c.cli();
  cli.add_option("--envs", o->envs, "matches the client plays at once")->check(CLI::PositiveNumber);
  cli.add_option("--workers", o->workers, "server worker threads (default: one per core)")
      ->check(CLI::NonNegativeNumber);
  cli.add_option("--seconds", o->seconds, "wall seconds per measurement")
      ->check(CLI::PositiveNumber);
  cli.add_option("--async", o->async_batch,
                 "async (EnvPool's send/recv): each recv takes this many ready matches")
      ->check(CLI::PositiveNumber);
  cli.add_option("--connect", o->connect,
                 "LCM URL of a running olympics-server to play on (default: one in process)");
  c.measure = [o] { return run_vector_bench(*o); };
  c.print = print_vector_report;
  return c;
}

}  // namespace olympics::bench
