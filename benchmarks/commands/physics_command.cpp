// olympics-bench physics [--json] [--seconds S] [--repeats R] [--threads T] [--no-mujoco]
#include "bench_command.h"
#include "physics_bench.h"

namespace olympics::bench {

BenchCommand physics_command(CLI::App& app) {
  BenchCommand c(app, "physics", "physics steps/s vs MuJoCo on the same MJCF");
  auto o = std::make_shared<PhysicsBenchOptions>();
  auto no_mujoco = std::make_shared<bool>(false);
  c.cli()
      .add_option("--seconds", o->seconds, "wall seconds per measurement")
      ->check(CLI::PositiveNumber);
  c.cli()
      .add_option("--repeats", o->repeats, "interleaved repeats (median reported)")
      ->check(CLI::PositiveNumber);
  c.cli().add_option("--threads", o->max_threads, "thread sweep up to this many (0: all cores)");
  c.cli().add_flag("--no-mujoco", *no_mujoco, "skip the MuJoCo side");
  c.measure = [o, no_mujoco] {
    o->with_mujoco = !*no_mujoco;
    return run_physics_bench(*o);
  };
  c.print = print_physics_report;
  return c;
}

}  // namespace olympics::bench
