// Self-play across a fleet's cells: `olympics-league selfplay --fleet` is the run's scheduler,
// one process that makes every decision as `olympics-league selfplay` does on one host. It keeps
// up to `lag` (--parallel) games queued or playing in the fleet's queue; cells lease and play
// them and store their results; as each result is stored the scheduler decides the next game
// from the results of games at least `lag` before it (SelfplayScheduler), so the same seed and
// snapshots give the same games as one host with --parallel `lag`. Snapshots travel through the
// database (fleet_snapshots.h). A scheduler killed and started again resumes from the database;
// cells keep playing what is queued meanwhile and wait for it.
#pragma once

#include <string>

#include "league_store.h"

namespace olympics::selfplay {

struct SelfplayFleetSettings {
  std::string db_url;       // postgresql://
  std::string fingerprint;  // the deployment's secret fingerprint (secret_fingerprint)
  bool quiet = false;       // no line per stored game
  double poll_s = 0.25;     // how often it reads the results cells stored
};

// Drives the run `spec` (created in the database already) until its last game is stored; 0.
// Throws std::invalid_argument when the database refuses it or a snapshot cannot be read.
int drive_selfplay_fleet(const TournamentSpec& spec, const SelfplayFleetSettings& settings);

}  // namespace olympics::selfplay
