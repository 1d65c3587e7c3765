// olympics-bench combat [--json] [--bouts N | --seeds A-B,..] [--pairings A_vs_B,..]
//                       [--threads T] [--seconds S] [--repeats R]
#include "bench_command.h"
#include "combat_bench.h"

namespace olympics::bench {

BenchCommand combat_command(CLI::App& app) {
  BenchCommand c(app, "combat",
                 "fencing / boxing: touches and punches per minute by pairing, ticks/s vs bare");
  auto o = std::make_shared<CombatBenchOptions>();
  auto& cli = c.cli();
  cli.add_option("--bouts", o->bouts, "bouts per sport and pairing (evaluation seeds 5001..5000+N)")
      ->check(CLI::PositiveNumber);
  add_seeds_option(cli, o->seeds, "bout");
  cli.add_option("--challenger", o->challenger,
                 "measure this policy (mlp:FILE) in slot 0 against scripted");
  cli.add_option("--sports", o->sports, "fencing, boxing (comma-separated)")->delimiter(',');
  cli.add_option("--pairings", o->pairings,
                 "only these pairings, A_vs_B (e.g. scripted_vs_scripted; comma-separated)")
      ->delimiter(',')
      ->check(
          [](const std::string& p) -> std::string {
            const size_t vs = p.find("_vs_");
            if (vs == std::string::npos || vs == 0 || vs + 4 >= p.size())
              return "'" + p + "' is not A_vs_B (e.g. scripted_vs_scripted, scripted_vs_zero)";
            return "";
          },
          "A_vs_B");
  cli.add_option("--threads", o->threads, "bouts played at once (figures do not depend on it)")
      ->check(CLI::PositiveNumber);
  cli.add_flag("--no-speed{false}", o->speed, "skip the 1v1 ticks/s measurement");
  cli.add_option("--seconds", o->seconds, "wall seconds per speed measurement")
      ->check(CLI::PositiveNumber);
  cli.add_option("--repeats", o->repeats, "interleaved repeats (median reported)")
      ->check(CLI::PositiveNumber);
  c.measure = [o] { return run_combat_bench(*o); };
  c.print = print_combat_report;
  return c;
}

}  // namespace olympics::bench
