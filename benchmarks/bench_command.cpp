#include "bench_command.h"

#include <cstdio>

#include "bench_support.h"

namespace olympics::bench {

BenchCommand::BenchCommand(CLI::App& app, const std::string& name, const std::string& summary)
    : cli_(app.add_subcommand(name, summary)) {
  cli_->add_flag("--json", *json_, "print one JSON object instead of a table");
}

int BenchCommand::run() const {
  const nlohmann::json report = measure();
  if (*json_)
    std::printf("%s\n", report.dump(2).c_str());
  else
    print(report);
  return status(report);
}

CLI::Option* add_seeds_option(CLI::App& cli, std::string& seeds, const std::string& what,
                              const std::string& name) {
  const auto seed_list = [](const std::string& text) {
    try {
      episode_seeds(text, 0);
      return std::string();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
  };
  return cli
      .add_option(name, seeds, what + " seeds instead, e.g. 5001-5500,7001-7200 (docs/figures.md)")
      ->check(seed_list);
}

}  // namespace olympics::bench
