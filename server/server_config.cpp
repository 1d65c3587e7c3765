#include "server_config.h"

#include <toml++/toml.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <sstream>
#include <stdexcept>

#include "channels.h"

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
  // A server id is letters, digits and '_' only (validate_server_config): a host name's '-' and
  // '.' become '_'.
  std::string id = std::string(host) + "_" + std::to_string(getpid());
  for (char& ch : id)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  c.host.server_id = id;
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
    in.read("scene_tracks", c.host.scene_tracks);
    in.read("view_port", c.view_port);
    in.read("view_host", c.view_host);
    in.read("secret_file", c.secret_file);
  }
  if (auto* t = root["sync"].as_table()) read_runtime(path, *t, "sync", c.host.sync);
  if (auto* t = root["realtime"].as_table()) read_runtime(path, *t, "realtime", c.host.realtime);
  if (auto* t = root["test"].as_table()) {
    TableReader in(path, *t, "test");
    in.read("drop_rate", c.transport.drop_rate);
    in.read("drop_seed", c.transport.drop_seed);
  }
  try {
    validate_server_config(c);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

void apply_flags(const ServerFlags& f, ServerConfig& c) {
  if (f.id) c.host.server_id = *f.id;
  if (f.lcm_url) c.transport.url = *f.lcm_url;
  if (f.secret_file) c.secret_file = *f.secret_file;
  if (f.results) c.results = *f.results;
  if (f.replay_dir) c.host.replay_dir = *f.replay_dir;
  if (f.lcm_logs) c.host.lcm_logs = true;
  if (f.no_scene_tracks) c.host.scene_tracks = false;
  if (f.unsigned_lan) c.unsigned_lan = true;
  if (f.view_port) c.view_port = *f.view_port;
  if (f.view_host) c.view_host = *f.view_host;
  if (f.capacity) c.host.capacity = *f.capacity;
  if (f.workers) c.host.workers = *f.workers;
  if (f.drop_rate) c.transport.drop_rate = *f.drop_rate;
  if (f.drop_seed) c.transport.drop_seed = *f.drop_seed;
  // Timing flags set both modes; missed ticks is the lockstep mode's.
  for (auto* r : {&c.host.sync, &c.host.realtime}) {
    if (f.action_deadline_ms) r->action_deadline_s = *f.action_deadline_ms / 1000.0;
    if (f.resend_ms) r->resend_interval_s = *f.resend_ms / 1000.0;
    if (f.silent_timeout_s) r->silent_timeout_s = *f.silent_timeout_s;
    if (f.join_timeout_s) r->join_timeout_s = *f.join_timeout_s;
  }
  if (f.max_missed_ticks) c.host.sync.max_missed_ticks = *f.max_missed_ticks;
}

namespace {

void in_range(const std::string& key, double value, double lo, double hi) {
  if (!(value >= lo && value <= hi)) {
    std::ostringstream out;
    out << "setting " << key << " must be in " << lo << ".." << hi << ", got " << value;
    throw std::invalid_argument(out.str());
  }
}

void validate_runtime(const std::string& mode, const RuntimeSettings& r) {
  in_range(mode + ".action_deadline_ms (--action-deadline-ms)", r.action_deadline_s * 1000, 1,
           600000);
  in_range(mode + ".max_missed_ticks (--max-missed-ticks)", r.max_missed_ticks, 1, 1000000);
  in_range(mode + ".resend_ms (--resend-ms)", r.resend_interval_s * 1000, 1, 10000);
  in_range(mode + ".silent_timeout_s (--silent-timeout-s)", r.silent_timeout_s, 0.1, 86400);
  in_range(mode + ".join_timeout_s (--join-timeout-s)", r.join_timeout_s, 0.1, 86400);
}

}  // namespace

void validate_server_config(const ServerConfig& c) {
  const std::string& id = c.host.server_id;
  // Match ids are "<server id>-<boot>-<n>" and a server claims the matches whose id starts with
  // its own and '-'; the id also names a channel LCM matches as a regular expression. So an id
  // holds no '-' (server "a" would claim the matches of "a-b") and no regex characters.
  const bool plain = std::all_of(id.begin(), id.end(), [](char ch) {
    return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
  });
  if (id.empty() || id.size() > 64 || !plain)
    throw std::invalid_argument(
        "setting server.id (--id) must be 1..64 characters, each a letter (A-Z, a-z), a digit "
        "or '_' (no '-', '.' or spaces: match ids are \"<id>-<boot>-<n>\"), got \"" +
        id + "\"");
  in_range("server.capacity (--capacity)", c.host.capacity, 1, 100000);
  in_range("server.workers (--workers)", c.host.workers, 0, 1024);
  in_range("server.view_port (--view-port)", c.view_port, 0, 65535);
  validate_runtime("sync", c.host.sync);
  validate_runtime("realtime", c.host.realtime);
  if (!(c.transport.drop_rate >= 0 && c.transport.drop_rate < 1))  // NaN too
    throw std::invalid_argument("setting test.drop_rate (--drop-rate) must be in [0, 1), got " +
                                std::to_string(c.transport.drop_rate));
  if (c.results.empty())
    throw std::invalid_argument(
        "setting server.results (--results) must name a SQLite file or a "
        "postgresql:// URL");
}

void check_server_resources(const ServerConfig& c) {
  const auto secret = protocol::load_secret(c.secret_file);  // throws saying what is wrong
  const std::string url = c.transport.url.empty() ? protocol::kDefaultLcmUrl : c.transport.url;
  // Unsigned, anyone who can reach the multicast group acts for any slot and forges results.
  if (!secret && !c.unsigned_lan && protocol::multicast_ttl(url) > 0)
    throw std::invalid_argument(
        "the LCM URL " + url +
        " reaches the LAN (ttl > 0) but no secret is given: anyone there "
        "could act for any slot and forge results. Give --secret FILE (make one with "
        "`olympics-server secret FILE`), keep ttl=0 for one host, or pass --unsigned-lan on a "
        "network you trust");
  const bool postgres = c.results.rfind("postgres", 0) == 0;
  if (!postgres) {
    const auto slash = c.results.rfind('/');
    const std::string folder = slash == std::string::npos ? "." : c.results.substr(0, slash);
    if (access(folder.empty() ? "/" : folder.c_str(), W_OK) != 0)
      throw std::invalid_argument("the results folder " + folder +
                                  " does not exist or is not writable (server.results)");
  }
}

std::string describe_server_config(const ServerConfig& c) {
  char text[1024];
  const auto& s = c.host.sync;
  std::snprintf(
      text, sizeof text,
      "config ok: id %s, lcm %s, capacity %d, workers %d, results %s, replays %s%s, secret %s\n"
      "live viewer: %s\n"
      "sync: deadline %.0f ms, %d missed ticks, resend %.0f ms, silent %.1f s, join %.0f s\n"
      "realtime: %d missed ticks, silent %.1f s\n",
      c.host.server_id.c_str(), c.transport.url.empty() ? "(default)" : c.transport.url.c_str(),
      c.host.capacity, c.host.workers, c.results.c_str(),
      c.host.replay_dir.empty() ? "(none)" : c.host.replay_dir.c_str(),
      c.host.replay_dir.empty() || !c.host.scene_tracks ? "" : " with scene tracks",
      c.secret_file.empty() ? "(none: $OLYMPICS_SECRET_FILE or unsigned)" : c.secret_file.c_str(),
      c.view_port ? ("http://" + c.view_host + ":" + std::to_string(c.view_port) + "/").c_str()
                  : "(none: --view-port)",
      s.action_deadline_s * 1000, s.max_missed_ticks, s.resend_interval_s * 1000,
      s.silent_timeout_s, s.join_timeout_s, c.host.realtime.max_missed_ticks,
      c.host.realtime.silent_timeout_s);
  return text;
}

}  // namespace olympics::server
