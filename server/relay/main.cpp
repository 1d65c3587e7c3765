// olympics-relay: a cell's LCM traffic to a learner on another host over one TCP connection
// admitted with the deployment's secret (docs/deploy.md, "Remote learners").
//
//   olympics-relay listen  --port 7700 [--bind 0.0.0.0] [--lcm-url U] [--secret FILE]   (cell)
//   olympics-relay connect --to CELL:7700 [--lcm-url U] [--secret FILE]               (learner)
#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>

#include "auth.h"
#include "tcp_relay.h"

namespace {
std::atomic<bool> stopping{false};
void on_signal(int) { stopping = true; }
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"olympics-relay: one cell's LCM traffic to a learner's host over TCP"};
  app.require_subcommand(1);
  std::string lcm_url, secret_file, bind_address = "0.0.0.0", to;
  int port = 7700;
  auto* listen_cmd = app.add_subcommand("listen", "on the cell's host: admit a learner's relay");
  listen_cmd->add_option("--port", port, "TCP port");
  listen_cmd->add_option("--bind", bind_address, "IPv4 address to listen on");
  auto* connect_cmd = app.add_subcommand("connect", "on the learner's host: join a cell");
  connect_cmd->add_option("--to", to, "the cell's relay, HOST:PORT")->required();
  for (auto* cmd : {listen_cmd, connect_cmd}) {
    cmd->add_option("--lcm-url", lcm_url, "this host's LCM URL (default: the project's, ttl=0)");
    cmd->add_option("--secret", secret_file,
                    "the deployment's secret file (default $OLYMPICS_SECRET_FILE)");
  }
  CLI11_PARSE(app, argc, argv);
  try {
    olympics::relay::RelaySettings settings{lcm_url, olympics::protocol::load_secret(secret_file)};
    olympics::relay::RelayCounts counts;
    if (*listen_cmd) olympics::relay::serve(settings, bind_address, port, counts);
    const auto colon = to.rfind(':');
    if (colon == std::string::npos) throw std::invalid_argument("--to wants HOST:PORT, got " + to);
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    olympics::relay::connect_and_relay(settings, to.substr(0, colon),
                                       std::stoi(to.substr(colon + 1)), counts, stopping);
    std::fprintf(stderr, "relay: done (%llu messages sent, %llu received)\n",
                 static_cast<unsigned long long>(counts.sent.load()),
                 static_cast<unsigned long long>(counts.received.load()));
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "olympics-relay: %s\n", e.what());
    return 2;
  }
}
