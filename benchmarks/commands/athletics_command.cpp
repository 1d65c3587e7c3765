// olympics-bench athletics [--json] [--episodes N | --seeds A-B,..] [--policies P,..]
//                          [--events E,..] [--no-speed] [--seconds S] [--repeats R]
//                          [--golf-address placed|walk]
#include "athletics_bench.h"
#include "bench_command.h"

namespace olympics::bench {

BenchCommand athletics_command(CLI::App& app) {
  BenchCommand c(
      app, "athletics",
      "long jump marks and fouls, high-jump leap-over rate per height, javelin valid rate and "
      "mark, hurdles completion, time and knocks, golf hit and holed rates, ticks/s");
  auto o = std::make_shared<AthleticsBenchOptions>();
  auto& cli = c.cli();
  cli.add_option("--episodes", o->episodes,
                 "episodes per policy, event and height (seeds 5001.., the evaluation seeds of "
                 "docs/figures.md)")
      ->check(CLI::PositiveNumber);
  add_seeds_option(cli, o->seeds, "athletics");
  cli.add_option("--policies", o->policies,
                 "policies (comma-separated; default zero,random,scripted)")
      ->delimiter(',');
  cli.add_option(
         "--events", o->events,
         "events (comma-separated): long_jump, standing_long_jump (0.8 m run-up), high_jump, "
         "high_jump_official (first try at 0.5 and 1.0 m), javelin, hurdles, golf")
      ->delimiter(',')
      ->check(CLI::IsMember({"long_jump", "standing_long_jump", "high_jump", "high_jump_official",
                             "javelin", "hurdles", "golf"}));
  cli.add_flag("--no-speed{false}", o->speed, "skip the competition_8 ticks/s measurement");
  cli.add_option("--seconds", o->seconds, "wall seconds per speed measurement")
      ->check(CLI::PositiveNumber);
  cli.add_option("--repeats", o->repeats, "interleaved repeats (median reported)")
      ->check(CLI::PositiveNumber);
  cli.add_option("--golf-address", o->golf_address,
                 "golf's address setting: placed (at address for every stroke) or walk (for the "
                 "first only; the policy walks to its ball)")
      ->check(CLI::IsMember({"placed", "walk"}));
  c.measure = [o] { return run_athletics_bench(*o); };
  c.print = print_athletics_report;
  return c;
}

}  // namespace olympics::bench
