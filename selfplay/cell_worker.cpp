#include "cell_worker.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <deque>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include "fleet_connection.h"
#include "fleet_snapshots.h"
#include "process.h"
#include "scheduler.h"

namespace olympics::selfplay {
namespace {

using namespace std::chrono_literals;
constexpr const char* kSetpriv = "/usr/bin/setpriv";

void sleep_s(double seconds) {
  std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
}

// The cell's second connection, on its own thread: hands finished results to the queue as soon
// as they are known (kept while the database is away), renews the cell's leases, and touches the
// health file. The games being played never wait on the database.
class Keeper {
 public:
  explicit Keeper(const CellSettings& settings)
      : settings_(settings),
        db_(settings.db_url, "cell " + settings.cell, settings.cell, false),
        thread_([this](std::stop_token stop) {
          while (!stop.stop_requested()) {
            try {
              tick();
            } catch (const std::exception& e) {  // a refusal the main thread meets too: go on
              std::fprintf(stderr, "cell %s: %s\n", settings_.cell.c_str(), e.what());
            }
            std::this_thread::sleep_for(200ms);
          }
        }) {}

  void add(const std::string& tournament, const FinishedFixture& result) {
    std::lock_guard lock(mutex_);
    outbox_.push_back({tournament, result});
  }
  void hold(const std::string& tournament) {
    std::lock_guard lock(mutex_);
    holding_ = tournament;
  }
  void wait_until_flushed() {
    for (;;) {
      {
        std::lock_guard lock(mutex_);
        if (outbox_.empty()) return;
      }
      std::this_thread::sleep_for(100ms);
    }
  }

 private:
  void tick() {
    if (!settings_.health_file.empty()) std::ofstream(settings_.health_file) << "ok\n";
    const auto now = std::chrono::steady_clock::now();
    std::string holding;
    std::optional<std::pair<std::string, FinishedFixture>> next;
    {
      std::lock_guard lock(mutex_);
      holding = holding_;
      if (!outbox_.empty()) next = outbox_.front();
    }
    const bool renew_due = !holding.empty() &&
                           now - last_renew_ > std::chrono::duration<double>(settings_.lease_s / 3);
    if (!next && !renew_due) return;
    db_.run([&](FixtureQueue& queue, LeagueStore*) {
      if (renew_due) {
        queue.renew(holding, settings_.lease_s);
        last_renew_ = now;
      }
      while (next) {
        const bool first = queue.store_result(next->first, next->second);
        std::fprintf(stderr, "cell %s: %s game %d%s\n", settings_.cell.c_str(), next->first.c_str(),
                     next->second.index,
                     first ? " stored" : " was stored already (played twice; the first counts)");
        std::lock_guard lock(mutex_);
        outbox_.pop_front();
        next.reset();
        if (!outbox_.empty()) next = outbox_.front();
      }
    });
  }

  const CellSettings& settings_;
  FleetConnection db_;
  std::mutex mutex_;
  std::deque<std::pair<std::string, FinishedFixture>> outbox_;
  std::string holding_;
  std::chrono::steady_clock::time_point last_renew_{};
  std::jthread thread_;  // last: it starts once everything it uses is made
};

// A game not played yet (a ranked fixture keeps its seats).
Game fresh_game(int index, int round, int home, int away, std::vector<int> seats = {}) {
  Game g;
  g.index = index, g.round = round, g.home = home, g.away = away;
  g.seats = std::move(seats);
  return g;
}

// The cell's runner plays exactly the fixtures it was given.
class NothingMore : public Scheduler {
 public:
  Verdict schedule(TournamentSpec&, const std::vector<Game>&, std::vector<Pairing>&) override {
    return Verdict::Finished;
  }
};

// Server ids are letters, digits and _.
std::string server_id_of(const std::string& cell) {
  std::string id = cell;
  for (char& c : id)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return id;
}

class Cell {
 public:
  explicit Cell(const CellSettings& settings)
      : settings_(settings),
        fingerprint_(secret_fingerprint(settings.runner.secret_file)),
        db_(settings.db_url, "cell " + settings.cell, settings.cell, true),
        keeper_(settings) {}

  int run() {
    start_server();
    for (;;) {
      std::vector<std::string> names;
      if (!db_.run([&](FixtureQueue& queue, LeagueStore*) {
            names = settings_.tournament.empty() ? queue.active_tournaments()
                                                 : std::vector{settings_.tournament};
          })) {
        sleep_s(settings_.poll_s);
        continue;
      }
      bool worked = false, open = false;
      for (const auto& t : names) {
        if (refused_.contains(t)) continue;
        std::vector<int> leased;
        RoundVerdict verdict = RoundVerdict::Wait;
        try {
          if (!db_.run([&](FixtureQueue& queue, LeagueStore* store) {
                leased = queue.lease(t, fingerprint_, lease_count(t, *store), settings_.lease_s);
                if (leased.empty()) verdict = queue_next_round(*store, queue, t, fingerprint_);
              })) {
            open = true;
            break;
          }
        } catch (const std::invalid_argument& e) {  // another secret, a self-play run
          if (!settings_.tournament.empty()) throw;
          refuse(t, e.what());
          continue;
        }
        if (!leased.empty()) {
          if (auto why = play(t, leased)) {
            if (!settings_.tournament.empty()) return 2;
            refuse(t, *why);
            continue;
          }
          worked = true;
          break;
        }
        if (verdict == RoundVerdict::Added) worked = true;
        if (verdict == RoundVerdict::Wait) open = true;
      }
      if (worked) continue;
      if (!open && !settings_.keep_waiting) {
        keeper_.wait_until_flushed();
        if (!refused_.empty()) {
          std::fprintf(stderr, "cell %s: no work left it can play (%zu tournament(s) refused)\n",
                       settings_.cell.c_str(), refused_.size());
          return 2;
        }
        std::fprintf(stderr, "cell %s: no work left\n", settings_.cell.c_str());
        return 0;
      }
      sleep_s(settings_.poll_s);
    }
  }

 private:
  void start_server() {
    if (!settings_.spawn_server) return;
    const std::string id = server_id_of(settings_.cell);
    // The server dies with the cell (a cell killed by SIGKILL leaves no server behind) where
    // util-linux's setpriv can ask the kernel for it; the policy workers, as on one host, are
    // left to finish their games.
    std::vector<std::string> argv;
    if (access(kSetpriv, X_OK) == 0) argv = {kSetpriv, "--pdeathsig", "KILL", "--"};
    argv.insert(argv.end(),
                {settings_.server_program, "serve", "--id", id, "--capacity",
                 std::to_string(settings_.server_capacity > 0 ? settings_.server_capacity
                                                              : settings_.runner.parallel),
                 "--results", settings_.runner.log_dir + "/" + id + "-results.db"});
    if (!settings_.runner.lcm_url.empty())
      argv.insert(argv.end(), {"--lcm-url", settings_.runner.lcm_url});
    if (!settings_.runner.secret_file.empty())
      argv.insert(argv.end(), {"--secret", settings_.runner.secret_file});
    server_ = std::make_unique<Process>(argv, settings_.runner.log_dir + "/" + id + "-server.log");
    server_id_ = id;
  }

  // A self-play run has only its lag of games queued at once: a cell leases no more than it
  // plays at once, leaving the others to other cells.
  int lease_count(const std::string& t, LeagueStore& store) {
    auto format = formats_.find(t);
    if (format == formats_.end()) {
      auto spec = store.find_tournament(t);
      format = formats_.emplace(t, spec ? spec->format : "").first;
    }
    return format->second == "selfplay" ? std::min(settings_.batch, settings_.runner.parallel)
                                        : settings_.batch;
  }

  // A cell serving every queued tournament leaves one it cannot play to the others and goes on.
  void refuse(const std::string& t, const std::string& why) {
    std::fprintf(stderr, "cell %s: skips tournament %s: %s\n", settings_.cell.c_str(), t.c_str(),
                 why.c_str());
    refused_[t] = why;
  }

  // Plays the leased fixtures on the cell's server(s); nothing, or why the cell refuses them (they
  // go back to the queue with the reason noted).
  std::optional<std::string> play(const std::string& t, const std::vector<int>& leased) {
    std::optional<TournamentSpec> spec;
    std::vector<Game> games;
    std::map<std::string, std::string> snapshots;
    while (!db_.run([&](FixtureQueue& queue, LeagueStore* store) {
      spec = store->find_tournament(t);
      games = store->games(t);
      if (spec) snapshots = fetch_snapshots(queue, *spec, snapshot_cache());
    }))
      sleep_s(settings_.poll_s);
    if (!spec)
      throw std::invalid_argument("the queue names tournament " + t + ", which has no row");
    // The whole tournament, so that game indices (and the match seeds derived from them) are the
    // ones of a single host; games not leased here count as decided for this runner.
    for (auto& g : games) {
      if (std::binary_search(leased.begin(), leased.end(), g.index)) {
        g = fresh_game(g.index, g.round, g.home, g.away, g.seats);
      } else if (g.status != GameStatus::Done) {
        g.status = GameStatus::Done, g.reason = "played elsewhere";
      }
    }
    LeagueStore local(":memory:");
    local.create_tournament(*spec);
    local.add_games(t, games);
    RunnerSettings runner = settings_.runner;
    runner.progress = false;
    runner.policy_files = snapshots;
    if (!server_id_.empty()) runner.servers = {server_id_};
    runner.on_game_done = [&](const Game& g) {
      keeper_.add(t, {g.index, g.match_id, g.home_score, g.reason, g.ticks, g.places});
    };
    keeper_.hold(t);
    try {
      TournamentRunner(local, *spec, runner, std::make_unique<NothingMore>()).run();
    } catch (const std::invalid_argument& e) {
      keeper_.wait_until_flushed();
      while (!db_.run([&](FixtureQueue& queue, LeagueStore*) { queue.give_back(t, e.what()); }))
        sleep_s(settings_.poll_s);
      std::fprintf(stderr,
                   "cell %s refuses the fixtures of %s: %s; they are back in the queue for "
                   "another cell\n",
                   settings_.cell.c_str(), t.c_str(), e.what());
      return e.what();
    }
    return std::nullopt;
  }

  std::string snapshot_cache() const {
    return settings_.snapshot_cache.empty()
               ? settings_.runner.log_dir + "/fleet-snapshots-" + server_id_of(settings_.cell)
               : settings_.snapshot_cache;
  }

  const CellSettings& settings_;
  std::map<std::string, std::string> formats_;  // tournament -> format, as leased
  std::string fingerprint_;
  FleetConnection db_;
  Keeper keeper_;
  std::unique_ptr<Process> server_;
  std::string server_id_;
  std::map<std::string, std::string> refused_;  // tournaments this cell cannot play, and why
};

}  // namespace

RoundVerdict queue_next_round(LeagueStore& store, FixtureQueue& queue,
                              const std::string& tournament, const std::string& fingerprint) {
  RoundVerdict verdict = RoundVerdict::Wait;
  queue.with_round_lock(tournament, [&] {
    if (queue.finished(tournament)) {
      verdict = RoundVerdict::Finished;
      return;
    }
    auto spec = store.find_tournament(tournament);
    if (!spec) throw std::invalid_argument("no tournament \"" + tournament + "\" to queue");
    if (spec->format == "selfplay") {
      // Its scheduler (olympics-league selfplay --fleet) queues each game once the results it
      // depends on are stored, and marks the run finished; cells only play.
      verdict = RoundVerdict::Wait;
      return;
    }
    auto games = store.games(tournament);
    // Games of a round a crash left unqueued are queued now; the round goes on.
    for (const auto& g : games)
      if (g.status != GameStatus::Done) {
        queue.queue_pending(tournament, fingerprint);
        return;
      }
    std::vector<Pairing> pairs;
    switch (make_tournament_scheduler()->schedule(*spec, games, pairs)) {
      case Scheduler::Verdict::Finished:
        queue.mark_finished(tournament);
        verdict = RoundVerdict::Finished;
        return;
      case Scheduler::Verdict::Wait:
        return;
      case Scheduler::Verdict::Added:
        break;
    }
    std::vector<Game> added;
    for (const auto& p : pairs) {
      Game g = fresh_game(static_cast<int>(games.size() + added.size()), p.round, p.home, p.away,
                          p.seats);
      if (p.away < 0) g.status = GameStatus::Done, g.home_score = 1, g.reason = "bye";
      added.push_back(g);
    }
    store.add_games(tournament, added);
    queue.queue_pending(tournament, fingerprint);
    verdict = RoundVerdict::Added;
  });
  return verdict;
}

int run_cell(const CellSettings& settings) { return Cell(settings).run(); }

}  // namespace olympics::selfplay
