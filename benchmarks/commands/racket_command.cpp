// olympics-bench racket [--json] [--episodes N] [--seconds S] [--repeats R]
#include "bench_command.h"
#include "racket_bench.h"

namespace olympics::bench {

BenchCommand racket_command(CLI::App& app) {
  BenchCommand c(app, "racket",
                 "tennis / table tennis: scripted touch rate, match ticks/s vs bare physics");
  auto o = std::make_shared<RacketBenchOptions>();
  auto& cli = c.cli();
  cli.add_option("--episodes", o->episodes, "ball-return episodes per sport and policy")
      ->check(CLI::PositiveNumber);
  cli.add_option("--seconds", o->seconds, "wall seconds per speed measurement")
      ->check(CLI::PositiveNumber);
  cli.add_option("--policies", o->policies,
                 "ball-return players: scripted, zero, random, mlp:FILE (comma-separated)")
      ->delimiter(',');
  cli.add_option("--sports", o->sports, "tennis, table_tennis (comma-separated)")->delimiter(',');
  cli.add_flag("--no-speed{false}", o->speed, "skip the 1v1 ticks/s measurement");
  cli.add_option("--repeats", o->repeats, "interleaved repeats (median reported)")
      ->check(CLI::PositiveNumber);
  c.measure = [o] { return run_racket_bench(*o); };
  c.print = print_racket_report;
  return c;
}

}  // namespace olympics::bench
