// olympics-bench: performance figures, printed side by side with their references.
//
//   olympics-bench <benchmark> [--json] [its options]      (olympics-bench <benchmark> --help)
//
// Each benchmark declares its subcommand in commands/<name>_command.cpp; `soak` runs an hour
// and is not for CI.
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "bench_command.h"

namespace olympics::bench {

// The registry: one line per benchmark, naming the command its file defines
// (BenchCommand <name>_command(CLI::App&) in namespace olympics::bench), in --help's order.
// Every line ends in a backslash, so a new benchmark is one added line.
// clang-format off
#define OLYMPICS_BENCHMARKS(X) \
  X(physics)                   \
  X(server)                    \
  X(racket)                    \
  X(soccer)                    \
  X(basketball)                \
  X(athletics)                 \
  X(combat)                    \
  X(soak)                      \
  X(vector)                    \
  X(fleet)                     \
  /* the list's end */
// clang-format on

#define OLYMPICS_DECLARE_BENCHMARK(name) BenchCommand name##_command(CLI::App& app);
OLYMPICS_BENCHMARKS(OLYMPICS_DECLARE_BENCHMARK)
#undef OLYMPICS_DECLARE_BENCHMARK

}  // namespace olympics::bench

int main(int argc, char** argv) {
  using namespace olympics::bench;
  CLI::App app{"Performance figures for the humanoid sports server"};
  app.require_subcommand(1);
  std::vector<BenchCommand> commands;
#define OLYMPICS_ADD_BENCHMARK(name) commands.push_back(name##_command(app));
  OLYMPICS_BENCHMARKS(OLYMPICS_ADD_BENCHMARK)
#undef OLYMPICS_ADD_BENCHMARK
  CLI11_PARSE(app, argc, argv);
  try {
    for (const auto& command : commands)
      if (command.chosen()) return command.run();
  } catch (const std::invalid_argument& e) {  // a request the benchmark cannot run, said why
    std::fprintf(stderr, "olympics-bench: %s\n", e.what());
    return 2;
  }
  return 0;
}
