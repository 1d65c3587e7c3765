#include "selfplay_fleet.h"

#include <chrono>
#include <cstdio>
#include <set>
#include <thread>

#include "fleet_connection.h"
#include "fleet_snapshots.h"
#include "matchmaking.h"

namespace olympics::selfplay {
namespace {

using Clock = std::chrono::steady_clock;
// With nothing stored for this long, the scheduler says what it waits for.
constexpr auto kQuietReport = std::chrono::seconds(30);

int open_games(const std::vector<Game>& games) {
  int open = 0;
  for (const auto& g : games) open += g.status != GameStatus::Done;
  return open;
}

class SelfplayFleet {
 public:
  SelfplayFleet(const TournamentSpec& spec, const SelfplayFleetSettings& settings)
      : spec_(spec),
        settings_(settings),
        options_(SelfplayOptions::from_json(spec.options)),
        scheduler_(options_),
        db_(settings.db_url, "the self-play scheduler of " + spec.name, "scheduler", true) {}

  int run() {
    last_news_ = Clock::now();
    bool finished = false;
    for (;;) {
      const bool connected =
          db_.run([&](FixtureQueue& queue, LeagueStore* store) { finished = step(queue, *store); });
      if (connected && finished) return 0;
      if (!connected) registered_ = false;  // what was half done is redone when it is back
      std::this_thread::sleep_for(std::chrono::duration<double>(settings_.poll_s));
    }
  }

 private:
  // Reads what the cells stored, queues what may be decided now; true once the run is over.
  bool step(FixtureQueue& queue, LeagueStore& store) {
    if (!registered_) {
      // Queued before (resumed): the queue checks this scheduler holds the run's secret, and
      // games added but not queued when it stopped are queued now.
      queue.queue_pending(spec_.name, settings_.fingerprint);
      queue.lease(spec_.name, settings_.fingerprint, 0, 1);
      upload_snapshots(queue, spec_);
      store.update_entrants(spec_);
      stored_entrants_ = spec_.entrants.size();
      registered_ = true;
    }
    auto games = store.games(spec_.name);
    report(games);
    for (;;) {
      const int open = open_games(games);
      if (open >= options_.lag) return false;  // the same games in flight as one host's
      std::vector<Pairing> pairs;
      switch (scheduler_.schedule(spec_, games, pairs)) {
        case Scheduler::Verdict::Finished:
          if (open > 0) return false;
          queue.mark_finished(spec_.name);
          return true;
        case Scheduler::Verdict::Wait:
          return false;
        case Scheduler::Verdict::Added:
          break;
      }
      if (spec_.entrants.size() != stored_entrants_) {
        upload_snapshots(queue, spec_);  // before any cell can see the new entrant
        store.update_entrants(spec_);
        stored_entrants_ = spec_.entrants.size();
      }
      std::vector<Game> added;
      for (const auto& p : pairs) {
        Game g;
        g.index = static_cast<int>(games.size() + added.size());
        g.round = p.round, g.home = p.home, g.away = p.away;
        added.push_back(g);
      }
      store.add_games(spec_.name, added);
      queue.queue_pending(spec_.name, settings_.fingerprint);
      games.insert(games.end(), added.begin(), added.end());
    }
  }

  // A line per game stored since the last look; one every kQuietReport while nothing comes.
  void report(const std::vector<Game>& games) {
    const auto now = Clock::now();
    int done = 0;
    for (const auto& g : games) {
      if (g.status != GameStatus::Done) continue;
      ++done;
      if (!reported_.insert(g.index).second || settings_.quiet || first_look_) continue;
      std::fprintf(stderr, "%s: game %d %s vs %s: %s (%s, cell %s)\n", spec_.name.c_str(), g.index,
                   spec_.entrants[g.home].name.c_str(), spec_.entrants[g.away].name.c_str(),
                   g.home_score == 1   ? "1-0"
                   : g.home_score == 0 ? "0-1"
                                       : "draw",
                   g.reason.c_str(), g.server_id.c_str());
      last_news_ = now;
    }
    if (first_look_ && done > 0)
      std::fprintf(stderr, "resuming %s: %d of %d games stored\n", spec_.name.c_str(), done,
                   options_.matches);
    first_look_ = false;
    if (now - last_news_ >= kQuietReport) {
      std::fprintf(stderr,
                   "%s: %d of %d games stored, %d queued or playing; waiting for cells "
                   "(olympics-league cell --db URL --name %s)\n",
                   spec_.name.c_str(), done, options_.matches, open_games(games),
                   spec_.name.c_str());
      last_news_ = now;
    }
  }

  TournamentSpec spec_;
  const SelfplayFleetSettings& settings_;
  SelfplayOptions options_;
  SelfplayScheduler scheduler_;
  FleetConnection db_;
  bool registered_ = false, first_look_ = true;
  size_t stored_entrants_ = 0;  // entrants the database holds (a lost database may cut a step)
  std::set<int> reported_;
  Clock::time_point last_news_;
};

}  // namespace

int drive_selfplay_fleet(const TournamentSpec& spec, const SelfplayFleetSettings& settings) {
  return SelfplayFleet(spec, settings).run();
}

}  // namespace olympics::selfplay
