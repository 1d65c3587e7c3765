// olympics-bench athletics [--json] [--episodes N | --seeds A-B,..] [--policies P,..]
//                          [--hurdles-policies P,..] [--no-speed] [--seconds S] [--repeats R]
#include "athletics_bench.h"
#include "bench_command.h"

namespace olympics::bench {

BenchCommand athletics_command(CLI::App& app) {
  BenchCommand c(
      app, "athletics",
      "long jump marks and fouls, high-jump leap-over rate per height, hurdles completion, "
      "time and knocks, ticks/s");
  auto o = std::make_shared<AthleticsBenchOptions>();
  auto& cli = c.cli();
  cli.add_option("--episodes", o->episodes, "episodes per policy, event and height (seeds 1..N)")
      ->check(CLI::PositiveNumber);
  add_seeds_option(cli, o->seeds, "athletics");
  cli.add_option("--policies", o->policies,
                 "policies for the jumps (comma-separated; none: skip them)")
      ->delimiter(',');
  cli.add_option("--hurdles-policies", o->hurdles_policies,
                 "policies for the hurdles (comma-separated; none: skip them)")
      ->delimiter(',');
  cli.add_flag("--no-speed{false}", o->speed, "skip the competition_8 ticks/s measurement");
  cli.add_option("--seconds", o->seconds, "wall seconds per speed measurement")
      ->check(CLI::PositiveNumber);
  cli.add_option("--repeats", o->repeats, "interleaved repeats (median reported)")
      ->check(CLI::PositiveNumber);
  c.measure = [o] { return run_athletics_bench(*o); };
  c.print = print_athletics_report;
  return c;
}

}  // namespace olympics::bench
