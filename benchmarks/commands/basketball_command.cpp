// olympics-bench basketball [--json] [--throws N | --seeds A-B,..] [--policies P,..]
//                           [--distances D,.. | --no-distances] [--per-throw]
//                           [--games A-B,.. [--game-seconds S]] [--no-free-throws]
//                           [--dribbles A-B,.. [--dribble-seconds S] [--per-dribble]]
#include "basketball_bench.h"
#include "bench_command.h"

namespace olympics::bench {

BenchCommand basketball_command(CLI::App& app) {
  BenchCommand c(app, "basketball",
                 "basketball: free throws made by policy, 1v1 and 2v2 ticks/s vs bare physics");
  auto o = std::make_shared<BasketballBenchOptions>();
  auto& cli = c.cli();
  cli.add_option("--throws", o->throws, "free throws per policy (evaluation seeds 5001..5000+N)")
      ->check(CLI::PositiveNumber);
  add_seeds_option(cli, o->seeds, "free-throw");
  cli.add_option("--policies", o->policies,
                 "free-throw shooters: scripted, zero, random, mlp:FILE (comma-separated)")
      ->delimiter(',');
  cli.add_option("--distances", o->scripted_distances,
                 "free-throw lines (m from the board) the scripted shooter also shoots from")
      ->delimiter(',');
  auto no_distances = std::make_shared<bool>(false);
  cli.add_flag("--no-distances", *no_distances, "the scripted shooter from the rule's line only");
  cli.add_flag("--per-throw", o->per_throw, "each scripted throw's release in the report");
  cli.add_option("--games", o->game_seeds,
                 "scripted 1v1 games, one per seed (ranges and seeds, comma-separated: "
                 "400001-400024)");
  cli.add_option("--game-seconds", o->game_s, "seconds of play per scripted 1v1 game")
      ->check(CLI::PositiveNumber);
  cli.add_option("--dribbles", o->dribble_seeds,
                 "the scripted standing dribble, one episode per seed (the first check ball of a "
                 "1v1: 1-40)");
  cli.add_option("--dribble-seconds", o->dribble_s, "seconds of dribbling per episode")
      ->check(CLI::PositiveNumber);
  cli.add_flag("--per-dribble", o->per_dribble, "each dribble episode in the report");
  cli.add_flag("--no-free-throws{false}", o->free_throws, "skip the free throws");
  cli.add_flag("--no-speed{false}", o->speed, "skip the ticks/s measurements");
  cli.add_option("--seconds", o->seconds, "wall seconds per speed measurement")
      ->check(CLI::PositiveNumber);
  cli.add_option("--repeats", o->repeats, "interleaved repeats (median reported)")
      ->check(CLI::PositiveNumber);
  c.measure = [o, no_distances] {
    if (*no_distances) o->scripted_distances.clear();
    return run_basketball_bench(*o);
  };
  c.print = print_basketball_report;
  return c;
}

}  // namespace olympics::bench
