// olympics-snapshot: look into a policy snapshot, or run it.
//
//   olympics-snapshot inspect FILE          layout and metadata
//   olympics-snapshot eval FILE < obs.txt   one line of observation floats in, one of actions out
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "mlp_snapshot.h"

int main(int argc, char** argv) {
  CLI::App app{"olympics-snapshot: inspect or run an MLP policy snapshot"};
  app.require_subcommand(1);
  std::string file;
  auto* inspect = app.add_subcommand("inspect", "print the layout and metadata");
  inspect->add_option("file", file, "snapshot (.safetensors)")->required();
  auto* eval =
      app.add_subcommand("eval", "read observations (one per line) on stdin, print actions");
  eval->add_option("file", file, "snapshot (.safetensors)")->required();
  CLI11_PARSE(app, argc, argv);
  try {
    auto snapshot = olympics::client::MlpSnapshot::load(file);
    if (*inspect) {
      std::printf("%s\n", snapshot.describe().c_str());
      return 0;
    }
    std::string line;
    std::vector<float> action(snapshot.action_size());
    while (std::getline(std::cin, line)) {
      std::istringstream in(line);
      std::vector<float> obs;
      for (float v; in >> v;) obs.push_back(v);
      snapshot.act(obs, action);
      for (size_t k = 0; k < action.size(); ++k) std::printf(k ? " %.9g" : "%.9g", action[k]);
      std::printf("\n");
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "olympics-snapshot: %s\n", e.what());
    return 2;
  }
}
