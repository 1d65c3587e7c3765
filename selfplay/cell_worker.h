// A cell of a fleet (docs/deploy.md): one olympics-server and the policy workers the league
// starts for it, in one network namespace (a pod, a host) talking LCM inside it only, taking its
// work from the fleet's FixtureQueue in PostgreSQL. It leases a batch of fixtures, plays them as
// the league plays games on one host (a TournamentRunner over its own server), hands each result
// to the queue as soon as it is known, and renews its lease meanwhile. When the database is lost
// it takes no new work, keeps its results and renews nothing, and goes on when it is back. It
// plays self-play runs' fixtures too (their scheduler, selfplay_fleet.h, queues them), and its
// workers play snapshots from its own copies of the database's (fleet_snapshots.h).
#pragma once

#include <string>

#include "fixture_queue.h"
#include "league_store.h"
#include "tournament_runner.h"

namespace olympics::selfplay {

struct CellSettings {
  std::string db_url;          // postgresql://
  std::string tournament;      // "" = every queued tournament, oldest first
  std::string cell;            // this cell's name (unique in the fleet)
  int batch = 8;               // fixtures leased at once
  double lease_s = 30;         // a lease not renewed this long returns its fixtures to the queue
  double poll_s = 1;           // how often an idle cell looks for work
  bool keep_waiting = false;   // stay when there is no work left (a Deployment), else exit 0
  bool spawn_server = false;   // start the cell's olympics-server (else one runs there already)
  std::string server_program;  // its program (olympics-server beside this one)
  int server_capacity = 0;     // its matches at once (0: --parallel; more leaves room for learners)
  std::string health_file;     // touched every second while the cell is well (an exec probe)
  std::string snapshot_cache;  // where the cell keeps its copies of snapshots ("": in log_dir)
  RunnerSettings runner;       // how games are played inside the cell
};

// Runs the cell until its work is done (0), or it is refused: another secret than the
// tournament's, a sport or settings its server does not host (2, the fixtures given back).
int run_cell(const CellSettings& settings);

enum class RoundVerdict { Added, Wait, Finished };
// Queues the tournament's next games when every game so far is done (one cell at a time, under
// the queue's round lock): the first round at `run --fleet`, later rounds of swiss and knockout
// from the cell that finds the round over.
RoundVerdict queue_next_round(LeagueStore& store, FixtureQueue& queue,
                              const std::string& tournament, const std::string& fingerprint);

}  // namespace olympics::selfplay
