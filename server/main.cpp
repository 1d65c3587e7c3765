// olympics-server: hosts matches for remote policy clients over LCM.
//
//   olympics-server serve [--config FILE] [flags]     host matches until SIGINT/SIGTERM
//   olympics-server sports                            list the sports and modes
//   olympics-server describe [SPORT] [--mode M] [--json]  layout of a sport (or all)
//   olympics-server results [--results DB] [--limit N] [--sport S] [--json]
//   olympics-server replay FILE                       re-run a match, check it reproduces
//   olympics-server view FILE [--port P] [--export HTML]  watch a match in the browser
#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "catalog.h"
#include "core/control_rate.h"
#include "match_host.h"
#include "registry.h"
#include "replay.h"
#include "results_store.h"
#include "scene_recorder.h"
#include "server_config.h"
#include "version.h"
#include "view_server.h"

namespace {

std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }

using namespace olympics;

int serve(server::ServerConfig config) {
  config.transport.auth = protocol::load_secret(config.secret_file);
  auto store = server::open_results_store(config.results);
  protocol::Transport transport(config.transport);
  server::LiveScenes live;
  std::unique_ptr<server::ViewServer> viewer;
  if (config.view_port) {
    config.host.live = &live;
    viewer = std::make_unique<server::ViewServer>(live, config.view_host, config.view_port);
    viewer->start();
  }
  server::MatchHost host(config.host, transport, *store);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  std::printf("olympics-server %s (protocol %d) id %s on %s; results in %s%s\n",
              protocol::kSoftwareVersion, protocol::kProtocolVersion, config.host.server_id.c_str(),
              transport.url().c_str(), store->describe().c_str(),
              config.transport.drop_rate > 0 ? " [TEST: dropping datagrams]" : "");
  if (viewer)
    std::printf("live viewer on http://%s:%d/ (pick a match to watch)\n", config.view_host.c_str(),
                viewer->port());
  if (transport.authenticating())
    std::printf("messages are signed and checked with the deployment secret\n");
  else
    std::printf(
        "NO SECRET: messages are neither signed nor checked; anyone on the network can "
        "act for any slot. For loopback experiments only (docs/security.md: --secret)\n");
  std::fflush(stdout);
  host.run(g_stop);
  std::printf(
      "stopped after %ld matches; refused %ld malformed and %ld unauthenticated messages, "
      "%ld replayed and %ld stale ones\n",
      host.finished_matches(), transport.malformed(), transport.unauthenticated(),
      transport.replayed(), transport.stale());
  return 0;
}

int describe_one(const sports::Sport& sport, const std::string& mode_arg) {
  std::printf("%s: %s\nmodes:", sport.name().c_str(), sport.summary().c_str());
  for (const auto& m : sport.modes().names()) std::printf(" %s", m.c_str());
  std::printf("\ndefault time limit: %g s; control at %d Hz\n", sport.default_time_limit_s(),
              core::kControlHz);
  const auto settings = sport.settings();
  if (!settings.empty()) {
    std::printf("settings (a match request's options, JSON):\n");
    for (const auto& s : settings)
      std::printf("  %-22s = %-10s %s [%s]%s\n", s.key.c_str(), s.default_value.dump().c_str(),
                  s.meaning.c_str(), s.allowed().c_str(),
                  s.official ? ("; official " + s.official->dump()).c_str() : "");
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
      for (const auto& f : b.fields)
        std::printf("    obs[%d:%d] %s\n", at + f.offset, at + f.offset + f.size, f.name.c_str());
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
    std::printf(
        "  referee calls (info.events[].call; * announced: olympics-agent --calls prints them):\n");
    for (const auto& c : l.calls)
      std::printf("   %s%-12s %s\n", c.announced ? "*" : " ", c.name.c_str(), c.meaning.c_str());
  }
  return 0;
}

// One sport or all of them, as text or as one JSON document.
int describe(const std::string& sport_name, const std::string& mode, bool json) {
  if (json) {
    if (sport_name.empty() && !mode.empty()) throw std::invalid_argument("--mode needs a sport");
    const auto doc = sport_name.empty()
                         ? sports::sport_catalog()
                         : sports::describe_sport(sports::sport_or_throw(sport_name), mode);
    std::printf("%s\n", doc.dump(1).c_str());
    return 0;
  }
  if (!sport_name.empty()) return describe_one(sports::sport_or_throw(sport_name), mode);
  if (!mode.empty()) throw std::invalid_argument("--mode needs a sport");
  for (const auto& name : sports::sport_names()) {
    describe_one(sports::sport_or_throw(name), "");
    std::printf("\n");
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

// The scene track of FILE: a .scene file, or a .replay's (beside it; made by re-running the
// replay when it is not there, e.g. for replays written without scene tracks).
std::string scene_track_for(const std::string& file) {
  auto ends_with = [&](const std::string& tail) {
    return file.size() >= tail.size() &&
           file.compare(file.size() - tail.size(), tail.size(), tail) == 0;
  };
  if (ends_with(".scene")) return file;
  if (!ends_with(".replay"))
    throw std::invalid_argument(file + " is neither a .replay nor a .scene file");
  const std::string scene = file.substr(0, file.size() - 7) + ".scene";
  if (std::ifstream(scene).good()) return scene;
  std::printf("no scene track beside %s: re-running the replay to make %s\n", file.c_str(),
              scene.c_str());
  server::record_scene_from_replay(server::read_replay(file), scene);
  return scene;
}

int view(const std::string& file, const std::string& host, int port, const std::string& export_to) {
  const std::string scene = scene_track_for(file);
  const std::string bytes = server::read_packed_scene_file(scene);
  const server::SceneTrack track = server::decode_scene(server::unpack_scene(bytes, scene));
  std::printf("%s: %s %s, %zu frames (%.1f s)\n", scene.c_str(),
              track.header.value("sport", "?").c_str(), track.header.value("mode", "?").c_str(),
              track.frames.size(),
              track.frames.size() / track.header.value("control_hz", double(core::kControlHz)));
  if (!export_to.empty()) {
    std::ofstream out(export_to, std::ios::binary);
    out << server::export_viewer_page(bytes);
    if (!out.flush()) throw std::runtime_error("cannot write " + export_to);
    std::printf("wrote %s: one file, open it in a browser\n", export_to.c_str());
    return 0;
  }
  server::ViewServer viewer(bytes, host, port);
  std::printf("watch it on http://%s:%d/ (Ctrl-C to stop)\n", host.c_str(), viewer.port());
  std::fflush(stdout);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  viewer.start();
  while (!g_stop) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  viewer.stop();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"olympics-server: authoritative match server for simulated humanoid sports"};
  app.require_subcommand(1);
  server::ServerConfig config = server::default_server_config();
  std::string config_file;

  auto* serve_cmd = app.add_subcommand("serve", "host matches until interrupted");
  server::ServerFlags flags;
  serve_cmd->add_option("--config", config_file, "TOML config file (flags override it)");
  serve_cmd->add_option("--id", flags.id, "server id: letters, digits and _ (default host_pid)");
  serve_cmd->add_option("--lcm-url", flags.lcm_url, "LCM provider URL");
  serve_cmd->add_option("--secret", flags.secret_file,
                        "the deployment's secret file: sign and check every message "
                        "(default $OLYMPICS_SECRET_FILE; docs/security.md)");
  serve_cmd->add_option("--capacity", flags.capacity, "matches hosted at once");
  serve_cmd->add_option("--workers", flags.workers, "threads stepping matches (0: one per core)");
  serve_cmd->add_option("--results", flags.results, "SQLite file or postgresql:// URL");
  serve_cmd->add_option("--replay-dir", flags.replay_dir, "write <match>.replay files here");
  serve_cmd->add_flag("--lcm-logs", flags.lcm_logs, "also write <match>.lcmlog (lcm-logplayer)");
  serve_cmd->add_flag("--unsigned-lan", flags.unsigned_lan,
                      "TRUSTED NETWORKS ONLY: serve without a secret on a URL with ttl > 0");
  serve_cmd->add_flag("--no-scene-tracks", flags.no_scene_tracks,
                      "do not write <match>.scene (the viewer's data) beside replays");
  serve_cmd->add_option("--view-port", flags.view_port,
                        "serve the live viewer on this HTTP port (docs/viewer.md)");
  serve_cmd->add_option("--view-host", flags.view_host,
                        "the live viewer's address (default 127.0.0.1: this machine only)");
  serve_cmd->add_option("--action-deadline-ms", flags.action_deadline_ms,
                        "how long a sync tick waits for actions");
  serve_cmd->add_option("--max-missed-ticks", flags.max_missed_ticks,
                        "sync: missed ticks in a row before a forfeit");
  serve_cmd->add_option("--resend-ms", flags.resend_ms, "sync: republish interval while waiting");
  serve_cmd->add_option("--silent-timeout-s", flags.silent_timeout_s,
                        "forfeit a client silent this long");
  serve_cmd->add_option("--join-timeout-s", flags.join_timeout_s,
                        "cancel a match not full after this long");
  bool dry_run = false;
  serve_cmd->add_flag("--dry-run", dry_run,
                      "check the config (ranges, the secret, the results folder), print it, exit");
  serve_cmd->add_option("--drop-rate", flags.drop_rate,
                        "TEST ONLY: drop this share of sent datagrams");
  serve_cmd->add_option("--drop-seed", flags.drop_seed, "TEST ONLY: seed of the drops");

  std::string secret_path;
  auto* secret_cmd = app.add_subcommand(
      "secret", "write a new random deployment secret to FILE (mode 600; never overwrites)");
  secret_cmd->add_option("file", secret_path, "where")->required();

  app.add_subcommand("sports", "list the sports and their modes");
  std::string sport_name, mode;
  auto* describe_cmd =
      app.add_subcommand("describe", "print a sport's observation and action layout");
  bool describe_json = false;
  describe_cmd->add_option("sport", sport_name, "sport name (none: every sport)");
  describe_cmd->add_option("--mode", mode, "one mode only");
  describe_cmd->add_flag("--json", describe_json,
                         "one JSON document (what the Python package ships as sports.json)");
  std::string describe_output;
  describe_cmd->add_option("-o,--output", describe_output, "write to this file, not stdout");

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

  std::string view_file, view_export, view_host = "127.0.0.1";
  int view_port = 8080;
  auto* view_cmd =
      app.add_subcommand("view", "watch a recorded match in the browser (docs/viewer.md)");
  view_cmd->add_option("file", view_file, "a .replay (its .scene beside it) or a .scene file")
      ->required();
  view_cmd->add_option("--port", view_port, "HTTP port (0: any free one)");
  view_cmd->add_option("--host", view_host, "address to listen on");
  view_cmd->add_option("--export", view_export,
                       "write one self-contained HTML page to this file instead of serving");

  CLI11_PARSE(app, argc, argv);
  try {
    if (*serve_cmd) {
      // The file first (if any), then the flags given on the command line win; then every
      // value is checked, so that nothing that would break matches gets to run.
      if (!config_file.empty()) server::load_server_config_file(config_file, config);
      server::apply_flags(flags, config);
      server::validate_server_config(config);
      server::check_server_resources(config);
      if (dry_run) {
        std::printf("%s", server::describe_server_config(config).c_str());
        return 0;
      }
      return serve(config);
    }
    if (*secret_cmd) {
      protocol::write_new_secret(secret_path);
      std::printf(
          "wrote a new secret to %s (readable by you only); give every server, league and "
          "agent of the deployment --secret %s\n",
          secret_path.c_str(), secret_path.c_str());
      return 0;
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
    if (*describe_cmd) {
      if (!describe_output.empty() && !std::freopen(describe_output.c_str(), "w", stdout))
        throw std::runtime_error("cannot write " + describe_output);
      return describe(sport_name, mode, describe_json);
    }
    if (*results_cmd) return results(results_location, limit, results_sport, json);
    if (*replay_cmd) return replay(replay_file);
    if (*view_cmd) return view(view_file, view_host, view_port, view_export);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "olympics-server: %s\n", e.what());
    return 2;
  }
  return 0;
}
