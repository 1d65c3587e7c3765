// olympics-server settings: a TOML file (--config) and flags, flags winning. Every key of the file
// is known; a typo or a wrong type is an error that names the file, line and key.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "match_host.h"
#include "transport.h"

namespace olympics::server {

struct ServerConfig {
  HostSettings host;
  protocol::TransportOptions transport;
  std::string results = "olympics-results.db";  // SQLite path or postgresql:// URL
  std::string secret_file;                      // "" = $OLYMPICS_SECRET_FILE, or none
  int view_port = 0;                            // live viewer's HTTP port; 0 = none
  std::string view_host = "127.0.0.1";          // where it listens (0.0.0.0: every interface)
  bool unsigned_lan = false;  // serve without a secret on a URL that leaves the host (ttl > 0)
};

// What the command line gave; each set one wins over the file.
struct ServerFlags {
  std::optional<std::string> id, lcm_url, secret_file, results, replay_dir, view_host;
  std::optional<int> capacity, workers, max_missed_ticks, view_port;
  std::optional<double> action_deadline_ms, resend_ms, silent_timeout_s, join_timeout_s;
  std::optional<double> drop_rate;
  std::optional<std::uint64_t> drop_seed;
  bool lcm_logs = false;
  bool no_scene_tracks = false;
  bool unsigned_lan = false;
};

ServerConfig default_server_config();
// Reads `path` over `config`. Throws std::runtime_error "FILE:LINE:COL: problem".
void load_server_config_file(const std::string& path, ServerConfig& config);
void apply_flags(const ServerFlags& flags, ServerConfig& config);
// Throws std::invalid_argument naming the first setting out of its range and the range.
void validate_server_config(const ServerConfig& config);
// Before serving (and for --dry-run): the secret loads, a URL that reaches the LAN has one (unless
// unsigned_lan), and the results folder is writable (throws saying which not).
void check_server_resources(const ServerConfig& config);
std::string describe_server_config(const ServerConfig& config);

}  // namespace olympics::server
