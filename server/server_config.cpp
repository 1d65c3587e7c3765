#include "server_config.h"

#include <toml++/toml.h>
#include <unistd.h>

#include <set>
#include <sstream>
#include <stdexcept>

namespace olympics::server {
namespace {

std::string where(const std::string& path, const toml::source_region& r) {
  std::ostringstream out;
  out << path << ":" << r.begin.line << ":" << r.begin.column;
  return out.str();
}

// Reads the keys of one table into settings, refusing keys it does not know.
class TableReader {
 public:
  TableReader(const std::string& path, const toml::table& table, std::string name)
      : path_(path), table_(table), name_(std::move(name)) {
    for (const auto& [key, node] : table_) {
      (void)node;
      keys_.insert(std::string(key.str()));
    }
  }
  ~TableReader() noexcept(false) {
    if (!keys_.empty() && std::uncaught_exceptions() == 0) {
      const std::string& key = *keys_.begin();
      throw std::runtime_error(where(path_, table_[key].node()->source()) + ": unknown key \"" +
                               key + "\" in [" + name_ + "]");
    }
  }
  template <typename T>
  void read(const char* key, T& out) {
    keys_.erase(key);
    auto node = table_[key];
    if (!node) return;
    if constexpr (std::is_same_v<T, std::string>) {
      if (auto v = node.value<std::string>()) return void(out = *v);
    } else if constexpr (std::is_same_v<T, bool>) {
      if (auto v = node.value<bool>()) return void(out = *v);
    } else if constexpr (std::is_integral_v<T>) {
      if (auto v = node.value<std::int64_t>()) return void(out = static_cast<T>(*v));
    } else {
      if (auto v = node.value<double>()) return void(out = *v);
    }
    throw std::runtime_error(where(path_, node.node()->source()) + ": [" + name_ + "] " + key +
                             " has the wrong type (see docs/server.md)");
  }
  void read_ms(const char* key, double& seconds_out) {
    double ms = seconds_out * 1000.0;
    read(key, ms);
    seconds_out = ms / 1000.0;
  }

 private:
  const std::string& path_;
  const toml::table& table_;
  std::string name_;
  std::set<std::string> keys_;
};

void read_runtime(const std::string& path, const toml::table& t, const char* name,
                  RuntimeSettings& r) {
  TableReader in(path, t, name);
  in.read_ms("action_deadline_ms", r.action_deadline_s);
  in.read("max_missed_ticks", r.max_missed_ticks);
  in.read_ms("resend_ms", r.resend_interval_s);
  in.read("silent_timeout_s", r.silent_timeout_s);
  in.read("join_timeout_s", r.join_timeout_s);
}

}  // namespace

ServerConfig default_server_config() {
  ServerConfig c;
  char host[256] = "server";
  gethostname(host, sizeof host - 1);
  c.host.server_id = std::string(host) + "-" + std::to_string(getpid());
  c.host.realtime.max_missed_ticks = 90;  // 3 s at 30 Hz
  return c;
}

void load_server_config_file(const std::string& path, ServerConfig& c) {
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    std::string what(e.description());
    if (what.find("File could not be opened") != std::string::npos)
      throw std::runtime_error(path + ": cannot open the config file");
    throw std::runtime_error(where(path, e.source()) + ": " + what);
  }
  const std::set<std::string> sections{"server", "sync", "realtime", "test"};
  for (const auto& [key, node] : root) {
    if (!sections.count(std::string(key.str())) || !node.is_table())
      throw std::runtime_error(where(path, node.source()) + ": unknown section \"" +
                               std::string(key.str()) +
                               "\" (known: [server], [sync], [realtime], [test])");
  }
  if (auto* t = root["server"].as_table()) {
    TableReader in(path, *t, "server");
    in.read("id", c.host.server_id);
    in.read("lcm_url", c.transport.url);
    in.read("capacity", c.host.capacity);
    in.read("workers", c.host.workers);
    in.read("results", c.results);
    in.read("replay_dir", c.host.replay_dir);
    in.read("lcm_logs", c.host.lcm_logs);
  }
  if (auto* t = root["sync"].as_table()) read_runtime(path, *t, "sync", c.host.sync);
  if (auto* t = root["realtime"].as_table()) read_runtime(path, *t, "realtime", c.host.realtime);
  if (auto* t = root["test"].as_table()) {
    TableReader in(path, *t, "test");
    in.read("drop_rate", c.transport.drop_rate);
    in.read("drop_seed", c.transport.drop_seed);
  }
  if (c.host.capacity < 1)
    throw std::runtime_error(path + ": [server] capacity must be at least 1");
  if (c.transport.drop_rate < 0 || c.transport.drop_rate >= 1)
    throw std::runtime_error(path + ": [test] drop_rate must be in [0, 1)");
}

}  // namespace olympics::server
