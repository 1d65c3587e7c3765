#include "bench_command.h"

#include <cstdio>

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

}  // namespace olympics::bench
