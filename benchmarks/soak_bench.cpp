#include "soak_bench.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

#include "auth.h"
#include "latency_histogram.h"
#include "league_store.h"
#include "play_match.h"
#include "process.h"
#include "results_store.h"

namespace olympics::bench {
namespace {

using Clock = std::chrono::steady_clock;
const std::vector<std::string> kClientSports = {"fencing", "boxing", "tennis", "table_tennis"};
constexpr const char* kServerId = "soak";

double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// What the players saw (each finished match, as its result told them), what went wrong, and the
// tick cycles they measured: per window (the ramp, each minute) and over the soak.
class Ledger {
 public:
  struct Finished {
    std::string match_id, by, reason;
    int ticks = 0;
  };
  void cycle(double ms) {
    std::lock_guard lock(mutex_);
    window_.add(ms), total_.add(ms);
  }
  LatencyHistogram take_window() {
    std::lock_guard lock(mutex_);
    return std::exchange(window_, LatencyHistogram{});
  }
  LatencyHistogram take_total() {
    std::lock_guard lock(mutex_);
    return std::exchange(total_, LatencyHistogram{});
  }
  void finished(Finished f) {
    std::lock_guard lock(mutex_);
    finished_.push_back(std::move(f));
  }
  void failed(const std::string& why) {
    std::lock_guard lock(mutex_);
    std::fprintf(stderr, "soak: %s\n", why.c_str());
    failures_.push_back(why);
  }
  std::size_t finished_count() {
    std::lock_guard lock(mutex_);
    return finished_.size();
  }
  std::vector<Finished> all_finished() {
    std::lock_guard lock(mutex_);
    return finished_;
  }
  std::vector<std::string> failures() {
    std::lock_guard lock(mutex_);
    return failures_;
  }

 private:
  std::mutex mutex_;
  LatencyHistogram window_, total_;
  std::vector<Finished> finished_;
  std::vector<std::string> failures_;
};

struct Deployment {
  std::string dir, url, secret;  // secret "": unsigned
  double match_seconds = 20;
};

// One match of client k's, both slots, scripted: its tick cycles go to the ledger, and so does
// its result.
void play_one(client::MatchClient& c, int k, int game, const Deployment& d, Ledger& ledger) {
  client::MatchRequest req;
  req.request_id = "soak-" + std::to_string(k) + "-" + std::to_string(game);
  req.sport = kClientSports[(k + game) % kClientSports.size()];
  req.seed = game, req.time_limit_s = d.match_seconds, req.server_id = kServerId;
  c.join(c.request_match(req, 60).match_id, {0, 1}, 60);
  client::PlayOptions play;
  play.policy = "scripted", play.policy_seed = 1000u * k + game;
  std::optional<Clock::time_point> last;
  play.on_observation = [&](const client::Observation&) {
    const auto now = Clock::now();
    if (last) ledger.cycle(ms_between(*last, now));
    last = now;
  };
  const auto& r = client::play_joined_match(c, play);
  ledger.finished({r.match_id, "client " + std::to_string(k), r.reason, r.ticks});
}

// Client k: matches back to back until told to stop, or until the ramp no longer wants it.
void play_back_to_back(int k, const Deployment& d, Ledger& ledger, const std::atomic<int>& active,
                       const std::atomic<bool>& stop) {
  try {
    client::ClientOptions co;
    co.lcm_url = d.url, co.agent_name = "soak" + std::to_string(k), co.secret_file = d.secret;
    client::MatchClient c(co);
    for (int game = 0; !stop && k < active; ++game) {
      try {
        play_one(c, k, game, d, ledger);
      } catch (const client::MatchError& e) {
        ledger.failed("client " + std::to_string(k) + ": " + e.what());
      }
    }
  } catch (const std::exception& e) {
    ledger.failed("client " + std::to_string(k) + " gave up: " + e.what());
  }
}

// Round-robin tournaments of four scripted and baseline entrants, fencing and boxing in turn,
// two games at once, until told to stop (the one under way is played out). Returns their names.
std::vector<std::string> run_leagues(const Deployment& d, Ledger& ledger,
                                     const std::atomic<bool>& stop) {
  std::vector<std::string> names;
  std::filesystem::create_directories(d.dir + "/league-logs");
  for (int t = 0; !stop; ++t) {
    names.push_back("soak-" + std::to_string(t));
    std::vector<std::string> argv = {program_beside_this_one("olympics-league"),
                                     "run",
                                     "--db",
                                     d.dir + "/league.db",
                                     "--name",
                                     names.back(),
                                     "--entrants",
                                     "scripted:1,scripted:2,random:3,zero",
                                     "--sport",
                                     t % 2 ? "boxing" : "fencing",
                                     "--time-limit",
                                     std::to_string(d.match_seconds),
                                     "--parallel",
                                     "2",
                                     "--servers",
                                     kServerId,
                                     "--lcm-url",
                                     d.url,
                                     "--log-dir",
                                     d.dir + "/league-logs",
                                     "--quiet"};
    if (!d.secret.empty()) argv.insert(argv.end(), {"--secret", d.secret});
    Process league(argv, d.dir + "/" + names.back() + ".log");
    const int code = league.wait(24 * 3600);
    if (code != 0)
      ledger.failed("league tournament " + names.back() + " exited " + std::to_string(code) +
                    ":\n" + league.output());
  }
  return names;
}

long rss_kb(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  return 0;
}

nlohmann::json window_json(const LatencyHistogram& h, double seconds) {
  return {{"cycle_ms_p50", h.percentile_ms(0.5)},
          {"cycle_ms_p99", h.percentile_ms(0.99)},
          {"cycle_ms_max", h.max_ms()},
          {"ticks_per_s", static_cast<double>(h.count()) / seconds}};
}

// Every match the players finished against what the server stored: none lost, none twice, none
// different, none that nobody finished, none left in progress, a replay for each.
nlohmann::json audit(const Deployment& d, Ledger& ledger,
                     const std::vector<std::string>& tournaments) {
  std::vector<Ledger::Finished> seen = ledger.all_finished();
  int unfinished_games = 0;
  selfplay::LeagueStore league(d.dir + "/league.db");
  for (const auto& name : tournaments)
    for (const auto& g : league.games(name)) {
      if (g.away < 0) continue;  // a bye
      if (g.status != selfplay::GameStatus::Done)
        ++unfinished_games;
      else
        seen.push_back({g.match_id, "league " + name, g.reason, g.ticks});
    }
  server::ResultsStore store(d.dir + "/results.db");
  const int left_in_progress = store.abort_unfinished(kServerId, std::time(nullptr));
  std::map<std::string, server::StoredMatch> stored;
  for (auto& m : store.recent(1 << 30)) stored.emplace(m.match_id, std::move(m));

  std::map<std::string, int> reports;
  int lost = 0, different = 0;
  std::vector<std::string> examples;
  for (const auto& f : seen) {
    ++reports[f.match_id];
    auto it = stored.find(f.match_id);
    if (it == stored.end()) {
      ++lost, examples.push_back("lost: " + f.match_id + " (" + f.by + ")");
    } else if (it->second.ticks != f.ticks || it->second.reason != f.reason) {
      ++different, examples.push_back("stored differently: " + f.match_id);
    }
  }
  int doubled = 0, unclaimed = 0;
  for (const auto& [id, n] : reports) doubled += n > 1;
  for (const auto& [id, m] : stored)
    if (!reports.count(id))
      ++unclaimed, examples.push_back("nobody finished " + id + ": " + m.reason);
  long replays = 0;
  for (const auto& entry : std::filesystem::directory_iterator(d.dir + "/replays"))
    replays += entry.is_regular_file();
  if (examples.size() > 20) examples.resize(20);
  return {{"finished_by_players", seen.size()},
          {"stored", stored.size()},
          {"lost", lost},
          {"reported_twice", doubled},
          {"stored_differently", different},
          {"stored_but_unfinished", unclaimed},
          {"left_in_progress", left_in_progress},
          {"league_games_not_done", unfinished_games},
          {"replays", replays},
          {"examples", examples}};
}

}  // namespace

nlohmann::json run_soak_bench(const SoakOptions& o) {
  Deployment d;
  d.dir = temp_dir();
  d.url = "udpm://239.255.76.67:" + std::to_string(18000 + getpid() % 10000) +
          "?ttl=0&recv_buf_size=8388608";
  d.match_seconds = o.match_seconds;
  if (o.signed_messages) protocol::write_new_secret(d.secret = d.dir + "/secret");
  std::vector<std::string> argv = {program_beside_this_one("olympics-server"),
                                   "serve",
                                   "--lcm-url",
                                   d.url,
                                   "--results",
                                   d.dir + "/results.db",
                                   "--replay-dir",
                                   d.dir + "/replays",
                                   "--id",
                                   kServerId,
                                   "--capacity",
                                   "1000"};
  if (o.workers > 0) argv.insert(argv.end(), {"--workers", std::to_string(o.workers)});
  if (!d.secret.empty()) argv.insert(argv.end(), {"--secret", d.secret});
  Process server(argv, d.dir + "/server.log");
  if (!server.wait_for_output("olympics-server", 60))
    throw std::runtime_error("olympics-server did not start:\n" + server.output());

  Ledger ledger;
  std::atomic<bool> stop{false};
  std::atomic<int> active{0};
  std::vector<std::thread> clients;
  auto grow = [&](int n) {
    active = n;
    while (static_cast<int>(clients.size()) < n)
      clients.emplace_back(play_back_to_back, static_cast<int>(clients.size()), std::cref(d),
                           std::ref(ledger), std::cref(active), std::cref(stop));
  };
  std::vector<std::string> tournaments;
  std::thread league;
  if (o.league) league = std::thread([&] { tournaments = run_leagues(d, ledger, stop); });

  // The ramp: more matches until the tick cycle's p99 misses the budget.
  nlohmann::json ramp = nlohmann::json::array();
  int held = o.matches;
  if (held == 0) {
    for (int n = o.ramp_step;; n += o.ramp_step) {
      grow(n);
      std::this_thread::sleep_for(std::chrono::duration<double>(o.ramp_window_s));
      const auto w = ledger.take_window();
      auto step = window_json(w, o.ramp_window_s);
      step["matches"] = n;
      ramp.push_back(step);
      std::fprintf(stderr, "soak ramp: %3d matches  p99 %6.1f ms  %6.0f ticks/s\n", n,
                   w.percentile_ms(0.99), static_cast<double>(w.count()) / o.ramp_window_s);
      if (w.count() == 0 || w.percentile_ms(0.99) >= o.p99_budget_ms) break;
      if (w.percentile_ms(0.99) < o.p99_budget_ms * o.ramp_headroom) held = n;
    }
    held = std::max(held, o.ramp_step);
  }
  grow(held);
  active = held;  // clients beyond it finish their match and leave
  for (int k = held; k < static_cast<int>(clients.size()); ++k) clients[k].join();
  clients.resize(held);

  // The soak.
  ledger.take_window(), ledger.take_total();
  const long rss_start = rss_kb(server.pid());
  const std::size_t finished_before = ledger.finished_count();
  nlohmann::json minutes = nlohmann::json::array();
  const auto start = Clock::now();
  for (int minute = 1; minute <= static_cast<int>(std::ceil(o.minutes)); ++minute) {
    const double window = std::min(60.0, o.minutes * 60 - (minute - 1) * 60.0);
    std::this_thread::sleep_until(start +
                                  std::chrono::duration<double>((minute - 1) * 60.0 + window));
    auto m = window_json(ledger.take_window(), window);
    m["minute"] = minute;
    m["finished"] = ledger.finished_count() - finished_before;
    m["server_rss_mb"] = rss_kb(server.pid()) / 1024.0;
    std::fprintf(stderr,
                 "soak minute %3d: p50 %5.1f ms  p99 %6.1f ms  max %7.1f ms  %6.0f ticks/s  %zu "
                 "matches done  server %.0f MB\n",
                 minute, m["cycle_ms_p50"].get<double>(), m["cycle_ms_p99"].get<double>(),
                 m["cycle_ms_max"].get<double>(), m["ticks_per_s"].get<double>(),
                 m["finished"].get<std::size_t>(), m["server_rss_mb"].get<double>());
    minutes.push_back(m);
  }
  const double soak_s = std::chrono::duration<double>(Clock::now() - start).count();
  const auto total = ledger.take_total();
  const long rss_end = rss_kb(server.pid());

  // Wind down: every match under way is played out, then the server stops as an operator would.
  stop = true;
  for (auto& t : clients) t.join();
  if (league.joinable()) league.join();
  server.signal(SIGINT);
  const int server_exit = server.wait(120);

  nlohmann::json report = {{"server_workers", o.workers},
                           {"cores", std::thread::hardware_concurrency()},
                           {"signed_messages", o.signed_messages},
                           {"league", o.league},
                           {"match_seconds", o.match_seconds},
                           {"p99_budget_ms", o.p99_budget_ms},
                           {"ramp_headroom", o.ramp_headroom},
                           {"ramp", ramp},
                           {"matches_held", held},
                           {"soak_minutes", soak_s / 60},
                           {"soak", window_json(total, soak_s)},
                           {"ticks_measured", total.count()},
                           {"minutes", minutes},
                           {"server_rss_mb_start", rss_start / 1024.0},
                           {"server_rss_mb_end", rss_end / 1024.0},
                           {"server_exit", server_exit},
                           {"tournaments", tournaments.size()},
                           {"audit", audit(d, ledger, tournaments)},
                           {"failures", ledger.failures()}};
  const auto& a = report["audit"];
  const bool clean = report["failures"].empty() && server_exit == 0 && a["lost"] == 0 &&
                     a["reported_twice"] == 0 && a["stored_differently"] == 0 &&
                     a["stored_but_unfinished"] == 0 && a["left_in_progress"] == 0 &&
                     a["league_games_not_done"] == 0 && a["replays"] == a["stored"];
  report["results_clean"] = clean;
  report["within_budget"] = total.percentile_ms(0.99) < o.p99_budget_ms;
  if (clean && !o.keep)
    std::filesystem::remove_all(d.dir);
  else
    report["folder"] = d.dir;
  return report;
}

void print_soak_report(const nlohmann::json& r) {
  const auto& s = r["soak"];
  const auto& a = r["audit"];
  std::printf(
      "soak: %d client matches at once (scripted fencing, boxing, tennis, table tennis, "
      "%.0f s each)%s, one server on %d cores%s\n",
      r["matches_held"].get<int>(), r["match_seconds"].get<double>(),
      r["league"].get<bool>() ? " + a league playing tournaments" : "", r["cores"].get<int>(),
      r["signed_messages"].get<bool>() ? ", signed" : "");
  for (const auto& step : r["ramp"])
    std::printf("  ramp %3d matches: tick cycle p99 %.1f ms, %.0f ticks/s\n",
                step["matches"].get<int>(), step["cycle_ms_p99"].get<double>(),
                step["ticks_per_s"].get<double>());
  std::printf(
      "  %.1f minutes, %lu ticks: tick cycle p50 %.1f ms, p99 %.1f ms, max %.1f ms "
      "(budget p99 < %.0f ms: %s)\n",
      r["soak_minutes"].get<double>(), r["ticks_measured"].get<unsigned long>(),
      s["cycle_ms_p50"].get<double>(), s["cycle_ms_p99"].get<double>(),
      s["cycle_ms_max"].get<double>(), r["p99_budget_ms"].get<double>(),
      r["within_budget"].get<bool>() ? "held" : "MISSED");
  std::printf("  server memory %.0f MB -> %.0f MB; exit %d\n",
              r["server_rss_mb_start"].get<double>(), r["server_rss_mb_end"].get<double>(),
              r["server_exit"].get<int>());
  std::printf(
      "  results: %d finished by players (%zu tournaments), %d stored, %d replays; lost %d, "
      "twice %d, different %d, unfinished %d, left in progress %d, league games not done %d"
      " -> %s\n",
      a["finished_by_players"].get<int>(), r["tournaments"].get<std::size_t>(),
      a["stored"].get<int>(), a["replays"].get<int>(), a["lost"].get<int>(),
      a["reported_twice"].get<int>(), a["stored_differently"].get<int>(),
      a["stored_but_unfinished"].get<int>(), a["left_in_progress"].get<int>(),
      a["league_games_not_done"].get<int>(),
      r["results_clean"].get<bool>() ? "clean" : "NOT CLEAN");
  for (const auto& e : a["examples"]) std::printf("    %s\n", e.get<std::string>().c_str());
  for (const auto& f : r["failures"]) std::printf("  failure: %s\n", f.get<std::string>().c_str());
  if (r.contains("folder")) std::printf("  kept: %s\n", r["folder"].get<std::string>().c_str());
}

}  // namespace olympics::bench
