// olympics-bench: performance figures, printed side by side with their references.
//
//   olympics-bench physics [--json] [--seconds S] [--repeats R] [--threads T] [--no-mujoco]
#include <CLI/CLI.hpp>
#include <cstdio>

#include "physics_bench.h"

int main(int argc, char** argv) {
  CLI::App app{"Performance figures for the humanoid sports server"};
  app.require_subcommand(1);
  bool json = false;
  olympics::bench::PhysicsBenchOptions physics;
  auto* phys = app.add_subcommand("physics", "physics steps/s vs MuJoCo on the same MJCF");
  phys->add_flag("--json", json, "print one JSON object instead of a table");
  phys->add_option("--seconds", physics.seconds, "wall seconds per measurement")
      ->check(CLI::PositiveNumber);
  phys->add_option("--repeats", physics.repeats, "interleaved repeats (median reported)")
      ->check(CLI::PositiveNumber);
  phys->add_option("--threads", physics.max_threads, "thread sweep up to this many (0: all cores)");
  bool no_mujoco = false;
  phys->add_flag("--no-mujoco", no_mujoco, "skip the MuJoCo side");
  CLI11_PARSE(app, argc, argv);

  if (*phys) {
    physics.with_mujoco = !no_mujoco;
    auto report = olympics::bench::run_physics_bench(physics);
    if (json)
      std::printf("%s\n", report.dump(2).c_str());
    else
      olympics::bench::print_physics_report(report);
  }
  return 0;
}
