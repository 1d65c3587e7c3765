// olympics-bench soccer [--json] [--kicks N | --seeds A-B,..] [--matches M | --match-seeds A-B,..]
//                       [--half-s S]
//                       [--policies P,..] [--no-speed] [--no-keeper]
#include "bench_command.h"
#include "soccer_bench.h"

namespace olympics::bench {

BenchCommand soccer_command(CLI::App& app) {
  BenchCommand c(app, "soccer",
                 "soccer: penalty kicks scored by policy, scripted goals per 10 min, 2v2 ticks/s");
  auto o = std::make_shared<SoccerBenchOptions>();
  auto& cli = c.cli();
  cli.add_option("--kicks", o->kicks, "penalty kicks per policy (evaluation seeds 5001..5000+N)")
      ->check(CLI::PositiveNumber);
  add_seeds_option(cli, o->seeds, "penalty kick");
  cli.add_option("--matches", o->matches,
                 "scripted 1v1 and 2v2 matches (evaluation seeds 5001..5000+M)")
      ->check(CLI::NonNegativeNumber);
  add_seeds_option(cli, o->match_seeds, "match", "--match-seeds");
  cli.add_option("--half-s", o->half_s, "seconds per half of those matches")
      ->check(CLI::PositiveNumber);
  cli.add_option("--policies", o->policies, "penalty kickers (comma-separated)")->delimiter(',');
  cli.add_flag("--no-speed{false}", o->speed, "skip the 2v2 ticks/s measurement");
  cli.add_flag("--no-keeper{false}", o->keeper,
               "skip the scripted kicker against the scripted goalkeeper");
  cli.add_option("--seconds", o->seconds, "wall seconds per speed measurement")
      ->check(CLI::PositiveNumber);
  cli.add_option("--repeats", o->repeats, "interleaved repeats (median reported)")
      ->check(CLI::PositiveNumber);
  c.measure = [o] { return run_soccer_bench(*o); };
  c.print = print_soccer_report;
  return c;
}

}  // namespace olympics::bench
