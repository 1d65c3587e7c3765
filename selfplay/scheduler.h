// What a league plays next. The runner asks whenever it could start another game; a scheduler
// answers with new games (and may add entrants), asks it to wait, or says it is finished.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "league_store.h"
#include "tournament.h"

namespace olympics::selfplay {

class Scheduler {
 public:
  enum class Verdict { Added, Wait, Finished };
  virtual ~Scheduler() = default;
  // `games` are all games so far (in index order); new pairings go to `out`. A scheduler may
  // append to spec.entrants (the runner stores them before the games).
  virtual Verdict schedule(TournamentSpec& spec, const std::vector<Game>& games,
                           std::vector<Pairing>& out) = 0;
};

// round-robin, double-round-robin, swiss, knockout: a round once the previous one is done.
std::unique_ptr<Scheduler> make_tournament_scheduler();

}  // namespace olympics::selfplay
