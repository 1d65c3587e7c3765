// olympics-server settings: a TOML file (--config) and flags, flags winning. Every key of the file
// is known; a typo or a wrong type is an error that names the file, line and key.
#pragma once

#include <string>

#include "match_host.h"
#include "transport.h"

namespace olympics::server {

struct ServerConfig {
  HostSettings host;
  protocol::TransportOptions transport;
  std::string results = "olympics-results.db";  // SQLite path or postgresql:// URL
};

ServerConfig default_server_config();
// Reads `path` over `config`. Throws std::runtime_error "FILE:LINE:COL: problem".
void load_server_config_file(const std::string& path, ServerConfig& config);

}  // namespace olympics::server
