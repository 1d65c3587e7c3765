// olympics-bench racket [--json] [--balls N | --episodes N] [--matches M] [--doubles D] [--serves
// S] [--seeds A-B,..]
// [--policies P,..]
//                       [--sports S,..] [--seconds S] [--repeats R] [--no-speed]
#include "bench_command.h"
#include "racket_bench.h"

namespace olympics::bench {

BenchCommand racket_command(CLI::App& app) {
  BenchCommand c(app, "racket",
                 "tennis / table tennis: scripted returns and rallies, match ticks/s vs bare "
                 "physics");
  auto o = std::make_shared<RacketBenchOptions>();
  auto& cli = c.cli();
  cli.add_option("--balls", o->balls, "ball return: balls fed per sport and policy")
      ->check(CLI::PositiveNumber);
  cli.add_option("--episodes", o->episodes, "ball return: this many episodes instead of --balls")
      ->check(CLI::PositiveNumber);
  cli.add_option("--matches", o->matches, "scripted 1v1 matches per sport (0: none)")
      ->check(CLI::NonNegativeNumber);
  cli.add_option("--doubles", o->doubles, "scripted 2v2 matches per sport (0: none)")
      ->check(CLI::NonNegativeNumber);
  cli.add_option("--serves", o->serves,
                 "scripted first serves per sport and mode, 1v1 and 2v2 (start: serve; 0: none)")
      ->check(CLI::NonNegativeNumber);
  add_seeds_option(cli, o->seeds, "episode and match (default: 100001 on, unseen by tuning)");
  cli.add_option("--policies", o->policies,
                 "ball-return players: scripted, zero, random, mlp:FILE (comma-separated)")
      ->delimiter(',');
  cli.add_option("--sports", o->sports, "tennis, table_tennis (comma-separated)")->delimiter(',');
  cli.add_flag("--no-speed{false}", o->speed, "skip the 1v1 ticks/s measurement");
  cli.add_option("--seconds", o->seconds, "wall seconds per speed measurement")
      ->check(CLI::PositiveNumber);
  cli.add_option("--repeats", o->repeats, "interleaved repeats (median reported)")
      ->check(CLI::PositiveNumber);
  c.measure = [o] { return run_racket_bench(*o); };
  c.print = print_racket_report;
  return c;
}

}  // namespace olympics::bench
