// olympics-bench soak [--json] [--minutes M] [--matches N] [--workers W] (an hour; not CI)
#include "bench_command.h"
#include "soak_bench.h"

namespace olympics::bench {

BenchCommand soak_command(CLI::App& app) {
  BenchCommand c(app, "soak",
                 "one server, as many matches as hold a p99 tick cycle under budget, for an hour; "
                 "then every result audited (exit 1 if not clean or over budget)");
  auto o = std::make_shared<SoakOptions>();
  auto no_league = std::make_shared<bool>(false), unsigned_messages = std::make_shared<bool>(false);
  auto& cli = c.cli();
  cli.add_option("--minutes", o->minutes, "soak length after the ramp")->check(CLI::PositiveNumber);
  cli.add_option("--matches", o->matches, "client matches at once (default: ramp to the most)")
      ->check(CLI::NonNegativeNumber);
  cli.add_option("--ramp-step", o->ramp_step, "matches added per ramp step")
      ->check(CLI::PositiveNumber);
  cli.add_option("--ramp-window", o->ramp_window_s, "wall seconds per ramp step")
      ->check(CLI::PositiveNumber);
  cli.add_option("--workers", o->workers, "server worker threads (default: one per core)")
      ->check(CLI::NonNegativeNumber);
  cli.add_option("--match-seconds", o->match_seconds, "simulated seconds per match")
      ->check(CLI::PositiveNumber);
  cli.add_option("--p99-budget-ms", o->p99_budget_ms, "tick cycle budget")
      ->check(CLI::PositiveNumber);
  cli.add_option("--ramp-headroom", o->ramp_headroom,
                 "hold the most matches whose ramp step kept p99 under this share of the budget")
      ->check(CLI::Range(0.05, 1.0));
  cli.add_flag("--no-league", *no_league, "clients only");
  cli.add_flag("--unsigned", *unsigned_messages, "no deployment secret");
  cli.add_flag("--keep", o->keep, "keep the folder of results, replays and logs");
  c.measure = [o, no_league, unsigned_messages] {
    o->league = !*no_league, o->signed_messages = !*unsigned_messages;
    return run_soak_bench(*o);
  };
  c.print = print_soak_report;
  c.status = [](const nlohmann::json& report) {
    return report["results_clean"].get<bool>() && report["within_budget"].get<bool>() ? 0 : 1;
  };
  return c;
}

}  // namespace olympics::bench
