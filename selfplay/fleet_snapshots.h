// Snapshots across a fleet: the entrants that are files (mlp:FILE) are read where the run is
// queued (the self-play scheduler, or `run --fleet`) and stored in the fleet's database; a cell
// writes them to a cache folder of its own and its policy workers play them from there. Cells
// need no shared folder and never see the learner's file system.
#pragma once

#include <map>
#include <string>

#include "fixture_queue.h"
#include "league_store.h"

namespace olympics::selfplay {

// Stores every file entrant of `spec` the database does not hold yet. Throws
// std::invalid_argument naming the file when one cannot be read.
void upload_snapshots(FixtureQueue& queue, const TournamentSpec& spec);

// Copies the stored snapshots of `spec`'s entrants into `cache_dir` (once each); the stored
// policy -> the local file its workers play. Entrants with no stored copy are left out (a
// tournament queued before snapshots travelled: their path is used as it is).
std::map<std::string, std::string> fetch_snapshots(FixtureQueue& queue, const TournamentSpec& spec,
                                                   const std::string& cache_dir);

}  // namespace olympics::selfplay
