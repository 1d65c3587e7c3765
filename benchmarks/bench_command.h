// One olympics-bench subcommand: its name, options and report. Each benchmark declares its own in
// commands/<name>_command.cpp and takes one line in olympics_bench.cpp's registry, so main stays
// the same size however many benchmarks there are.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

namespace olympics::bench {

class BenchCommand {
 public:
  // Adds subcommand `name` with its --json flag to olympics-bench's `app`.
  BenchCommand(CLI::App& app, const std::string& name, const std::string& summary);

  // The subcommand, to add the benchmark's own options to.
  CLI::App& cli() { return *cli_; }
  bool chosen() const { return cli_->parsed(); }

  // What the command measures (run after parsing), how its report prints as a table, and the
  // exit status the report makes (by default 0).
  std::function<nlohmann::json()> measure;
  std::function<void(const nlohmann::json&)> print;
  std::function<int(const nlohmann::json&)> status = [](const nlohmann::json&) { return 0; };

  // Measures, prints the report (one JSON object with --json, else the table): the exit status.
  int run() const;

 private:
  CLI::App* cli_;
  std::shared_ptr<bool> json_ = std::make_shared<bool>(false);
};

// Adds a --seeds option (e.g. 5001-5500,7001-7200; docs/figures.md) to `cli`, refused at parsing
// with what was wrong; `name` for a second seed list (--match-seeds).
CLI::Option* add_seeds_option(CLI::App& cli, std::string& seeds, const std::string& what,
                              const std::string& name = "--seeds");

}  // namespace olympics::bench
