// olympics-bench server [--json] [--seconds S] [--matches M] [--workers W] [--vector] [--async K]
#include "bench_command.h"
#include "server_bench.h"

namespace olympics::bench {

BenchCommand server_command(CLI::App& app) {
  BenchCommand c(app, "server", "match ticks/s over LCM vs bare physics, round-trip latency");
  auto o = std::make_shared<ServerBenchOptions>();
  auto no_pin = std::make_shared<bool>(false);
  auto& cli = c.cli();
  cli.add_option("--seconds", o->seconds, "wall seconds to measure")->check(CLI::PositiveNumber);
  cli.add_option("--matches", o->matches, "concurrent matches")->check(CLI::PositiveNumber);
  cli.add_option("--workers", o->workers, "server worker threads")->check(CLI::PositiveNumber);
  cli.add_flag("--no-pin", *no_pin, "let the OS place the server's workers");
  cli.add_option("--lcm-provider", o->provider,
                 "udpm (one port for all) or mpudpm (channels hashed over 64 ports)")
      ->check(CLI::IsMember({"udpm", "mpudpm"}));
  cli.add_flag("--signed", o->signed_messages,
               "with a deployment secret: every message signed and checked");
  cli.add_flag("--vector", o->vector_client,
               "one vector client plays every match (bundled traffic), not one client each");
  cli.add_option("--async", o->async_batch,
                 "with --vector: async (EnvPool's send/recv), each recv taking this many ready "
                 "matches")
      ->check(CLI::PositiveNumber);
  cli.add_option("--live-viewers", o->live_viewers,
                 "this many HTTP clients watch the matches live (the viewer's cost)")
      ->check(CLI::NonNegativeNumber);
  c.measure = [o, no_pin] {
    o->pin = !*no_pin;
    return run_server_bench(*o);
  };
  c.print = print_server_report;
  return c;
}

}  // namespace olympics::bench
