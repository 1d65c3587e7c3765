// olympics-server: hosts matches for remote policy clients over LCM.
//
//   olympics-server serve [--config FILE] [flags]     host matches until SIGINT/SIGTERM
//   olympics-server sports                            list the sports and modes
//   olympics-server describe SPORT [--mode M]         observation / action layout of a sport
//   olympics-server results [--results DB] [--limit N] [--sport S] [--json]
//   olympics-server replay FILE                       re-run a match, check it reproduces
#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <nlohmann/json.hpp>

#include "core/control_rate.h"
#include "match_host.h"
#include "registry.h"
#include "replay.h"
#include "results_store.h"
#include "server_config.h"
#include "version.h"

namespace {

std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }

using namespace olympics;

int serve(server::ServerConfig config) {
  auto store = server::open_results_store(config.results);
  protocol::Transport transport(config.transport);
  server::MatchHost host(config.host, transport, *store);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  std::printf("olympics-server %s (protocol %d) id %s on %s; results in %s%s\n",
              protocol::kSoftwareVersion, protocol::kProtocolVersion, config.host.server_id.c_str(),
              transport.url().c_str(), store->describe().c_str(),
              config.transport.drop_rate > 0 ? " [TEST: dropping datagrams]" : "");
  std::fflush(stdout);
  host.run(g_stop);
  std::printf("stopped after %ld matches; refused %ld malformed messages\n",
              host.finished_matches(), transport.malformed());
  return 0;
}

int describe(const std::string& sport_name, const std::string& mode_arg) {
  const sports::Sport& sport = sports::sport_or_throw(sport_name);
  std::printf("%s: %s\nmodes:", sport.name().c_str(), sport.summary().c_str());
  for (const auto& m : sport.modes().names()) std::printf(" %s", m.c_str());
  std::printf("\ndefault time limit: %g s; control at %d Hz\n", sport.default_time_limit_s(),
              core::kControlHz);
  const auto settings = sport.settings();
  if (!settings.empty()) {
    std::printf("settings (a match request's options, JSON):\n");
    for (const auto& s : settings)
      std::printf("  %-22s = %-10s %s [%s]\n", s.key.c_str(), s.default_value.dump().c_str(),
                  s.meaning.c_str(), s.allowed().c_str());
  }
  std::vector<std::string> modes =
      mode_arg.empty() ? sport.modes().names() : std::vector<std::string>{mode_arg};
  for (const auto& mode : modes) {
    const sports::ModeSpec& spec = sport.modes().at(mode);
    const sports::Layout l = sport.layout(mode);
    std::string teams;
    for (int s = 0; s < spec.slot_count(); ++s) {
      if (s > 0) teams += ' ';
      teams += std::to_string(s) + ":" + std::to_string(spec.slot_teams[s]);
    }
    std::printf("\nmode %s (%s): slots:teams %s; observation %d floats, action %d floats\n",
                mode.c_str(), spec.summary.c_str(), teams.c_str(), l.observation_size(),
                l.action_size());
    int at = 0;
    for (const auto& b : l.observation) {
      std::printf("  obs[%d:%d] %-16s (%s) %s\n", at, at + b.size, b.name.c_str(), b.units.c_str(),
                  b.meaning.c_str());
      at += b.size;
    }
    at = 0;
    for (const auto& b : l.action) {
      std::printf("  act[%d:%d] %-16s (%s) %s\n", at, at + b.size, b.name.c_str(), b.units.c_str(),
                  b.meaning.c_str());
      at += b.size;
    }
    std::printf("  reward = weighted sum of the terms (each sent by name):\n");
    for (const auto& t : l.rewards)
      std::printf("    %-12s x %-5g %s\n", t.name.c_str(), t.weight, t.meaning.c_str());
    std::printf("  referee calls (info.events[].call):\n");
    for (const auto& c : l.calls) std::printf("    %-12s %s\n", c.name.c_str(), c.meaning.c_str());
  }
  return 0;
}

std::string scores_text(const std::vector<double>& scores) {
  std::string out;
  char buf[32];
  for (double s : scores)
    std::snprintf(buf, sizeof buf, "%.2f", s), out += (out.empty() ? "" : "-") + std::string(buf);
  return out;
}

int results(const std::string& location, int limit, const std::string& sport, bool json) {
  auto store = server::open_results_store(location);
  auto rows = store->recent(limit, sport);
  nlohmann::json out = nlohmann::json::array();
  for (const auto& m : rows) {
    if (json) {
      nlohmann::json p = nlohmann::json::array();
      for (const auto& x : m.participants)
        p.push_back({{"slot", x.slot},
                     {"team", x.team},
                     {"agent", x.agent},
                     {"policy", x.policy},
                     {"policy_version", x.policy_version}});
      out.push_back({{"match_id", m.match_id},
                     {"sport", m.sport},
                     {"mode", m.mode},
                     {"seed", m.seed},
                     {"ticks", m.ticks},
                     {"wall_time_s", m.wall_time_s},
                     {"reason", m.reason},
                     {"winner_team", m.winner_team},
                     {"scores", m.scores},
                     {"participants", p},
                     {"options", nlohmann::json::parse(m.options, nullptr, false)},
                     {"server_id", m.server_id},
                     {"finished_at_unix", m.finished_at_unix}});
      continue;
    }
    char when[32];
    std::time_t t = static_cast<std::time_t>(m.finished_at_unix);
    std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S", std::gmtime(&t));
    std::string teams;
    for (const auto& x : m.participants)
      teams += (teams.empty() ? "" : ", ") + std::to_string(x.team) + ":" + x.agent;
    std::printf("%s  %-18s %-8s %-5s %5d ticks  scores %-14s winner %-4s %-22s [%s]\n", when,
                m.match_id.c_str(), m.sport.c_str(), m.mode.c_str(), m.ticks,
                scores_text(m.scores).c_str(),
                m.winner_team < 0 ? "none" : std::to_string(m.winner_team).c_str(),
                m.reason.c_str(), teams.c_str());
  }
  if (json)
    std::printf("%s\n", out.dump(2).c_str());
  else if (rows.empty())
    std::printf("no matches in %s\n", store->describe().c_str());
  return 0;
}

int replay(const std::string& path) {
  server::Replay r = server::read_replay(path);
  std::printf("replaying %s: %s %s, seed %s, %d ticks\n", path.c_str(),
              r.header.value("sport", "?").c_str(), r.header.value("mode", "?").c_str(),
              r.header["seed"].dump().c_str(), r.ticks());
  server::ReplayCheck check = server::verify_replay(r);
  std::printf("%s%s\n", check.report.c_str(),
              check.identical ? "REPRODUCED: identical result and final state"
                              : "MISMATCH: the re-run differs from the recording");
  return check.identical ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"olympics-server: authoritative match server for simulated humanoid sports"};
  app.require_subcommand(1);
  server::ServerConfig config = server::default_server_config();
  std::string config_file;

  auto* serve_cmd = app.add_subcommand("serve", "host matches until interrupted");
  serve_cmd->add_option("--config", config_file, "TOML config file (flags override it)");
  serve_cmd->add_option("--id", config.host.server_id, "server id (default host-pid)");
  serve_cmd->add_option("--lcm-url", config.transport.url, "LCM provider URL");
  serve_cmd->add_option("--capacity", config.host.capacity, "matches hosted at once")
      ->check(CLI::PositiveNumber);
  serve_cmd->add_option("--workers", config.host.workers,
                        "threads stepping matches (0: one per core)");
  serve_cmd->add_option("--results", config.results, "SQLite file or postgresql:// URL");
  serve_cmd->add_option("--replay-dir", config.host.replay_dir, "write <match>.replay files here");
  serve_cmd->add_flag("--lcm-logs", config.host.lcm_logs,
                      "also write <match>.lcmlog (lcm-logplayer)");
  double deadline_ms = -1, resend_ms = -1, silent_s = -1, join_s = -1;
  int missed = -1;
  serve_cmd->add_option("--action-deadline-ms", deadline_ms,
                        "sync: how long a tick waits for actions");
  serve_cmd->add_option("--max-missed-ticks", missed,
                        "sync: missed ticks in a row before a forfeit");
  serve_cmd->add_option("--resend-ms", resend_ms, "sync: republish interval while waiting");
  serve_cmd->add_option("--silent-timeout-s", silent_s, "forfeit a client silent this long");
  serve_cmd->add_option("--join-timeout-s", join_s, "cancel a match not full after this long");
  bool dry_run = false;
  serve_cmd->add_flag("--dry-run", dry_run, "check the config, print the settings, exit");
  serve_cmd->add_option("--drop-rate", config.transport.drop_rate,
                        "TEST ONLY: drop this share of sent datagrams");
  serve_cmd->add_option("--drop-seed", config.transport.drop_seed, "TEST ONLY: seed of the drops");

  app.add_subcommand("sports", "list the sports and their modes");
  std::string sport_name, mode;
  auto* describe_cmd =
      app.add_subcommand("describe", "print a sport's observation and action layout");
  describe_cmd->add_option("sport", sport_name, "sport name")->required();
  describe_cmd->add_option("--mode", mode, "one mode only");

  std::string results_location = config.results, results_sport;
  int limit = 20;
  bool json = false;
  auto* results_cmd = app.add_subcommand("results", "print recent match results");
  results_cmd->add_option("--results", results_location, "SQLite file or postgresql:// URL");
  results_cmd->add_option("--limit", limit, "how many")->check(CLI::PositiveNumber);
  results_cmd->add_option("--sport", results_sport, "only this sport");
  results_cmd->add_flag("--json", json, "JSON instead of a table");

  std::string replay_file;
  auto* replay_cmd =
      app.add_subcommand("replay", "re-run a recorded match and check it reproduces");
  replay_cmd->add_option("file", replay_file, "a .replay file")->required();

  CLI11_PARSE(app, argc, argv);
  try {
    if (*serve_cmd) {
      if (!config_file.empty()) {
        // The file first, then flags given on the command line win.
        server::ServerConfig from_file = server::default_server_config();
        server::load_server_config_file(config_file, from_file);
        auto flags = config;
        config = from_file;
        if (serve_cmd->count("--id")) config.host.server_id = flags.host.server_id;
        if (serve_cmd->count("--lcm-url")) config.transport.url = flags.transport.url;
        if (serve_cmd->count("--capacity")) config.host.capacity = flags.host.capacity;
        if (serve_cmd->count("--workers")) config.host.workers = flags.host.workers;
        if (serve_cmd->count("--results")) config.results = flags.results;
        if (serve_cmd->count("--replay-dir")) config.host.replay_dir = flags.host.replay_dir;
        if (serve_cmd->count("--lcm-logs")) config.host.lcm_logs = flags.host.lcm_logs;
        if (serve_cmd->count("--drop-rate")) config.transport.drop_rate = flags.transport.drop_rate;
        if (serve_cmd->count("--drop-seed")) config.transport.drop_seed = flags.transport.drop_seed;
      }
      for (auto* r : {&config.host.sync, &config.host.realtime}) {
        if (deadline_ms >= 0) r->action_deadline_s = deadline_ms / 1000.0;
        if (resend_ms > 0) r->resend_interval_s = resend_ms / 1000.0;
        if (silent_s > 0) r->silent_timeout_s = silent_s;
        if (join_s > 0) r->join_timeout_s = join_s;
      }
      if (missed > 0) config.host.sync.max_missed_ticks = missed;
      if (dry_run) {
        std::printf(
            "config ok: id %s, lcm %s, capacity %d, workers %d, results %s, replays %s\n"
            "sync: deadline %.0f ms, %d missed ticks, resend %.0f ms, silent %.1f s, join %.0f s\n"
            "realtime: %d missed ticks, silent %.1f s\n",
            config.host.server_id.c_str(),
            config.transport.url.empty() ? "(default)" : config.transport.url.c_str(),
            config.host.capacity, config.host.workers, config.results.c_str(),
            config.host.replay_dir.empty() ? "(none)" : config.host.replay_dir.c_str(),
            config.host.sync.action_deadline_s * 1000, config.host.sync.max_missed_ticks,
            config.host.sync.resend_interval_s * 1000, config.host.sync.silent_timeout_s,
            config.host.sync.join_timeout_s, config.host.realtime.max_missed_ticks,
            config.host.realtime.silent_timeout_s);
        return 0;
      }
      return serve(config);
    }
    if (app.got_subcommand("sports")) {
      for (const auto& name : sports::sport_names()) {
        const auto& s = sports::sport_or_throw(name);
        std::printf("%-10s %s\n           modes:", name.c_str(), s.summary().c_str());
        for (const auto& m : s.modes().names()) std::printf(" %s", m.c_str());
        std::printf("\n");
      }
      return 0;
    }
    if (*describe_cmd) return describe(sport_name, mode);
    if (*results_cmd) return results(results_location, limit, results_sport, json);
    if (*replay_cmd) return replay(replay_file);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "olympics-server: %s\n", e.what());
    return 2;
  }
  return 0;
}
