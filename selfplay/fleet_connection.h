// One connection to a fleet's database (the queue, and the league's own tables) that survives
// losing it: work that fails on a lost connection drops it, says once that its owner is paused,
// and reports false; the next call connects again and says it goes on. A database that answers
// "no" (credentials, a missing database) is not waited for: that throws std::invalid_argument.
// Used by cells and by the self-play scheduler of a fleet.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "fixture_queue.h"
#include "league_store.h"

namespace olympics::selfplay {

class FleetConnection {
 public:
  // `who` names the owner in messages ("cell c1"); `queue_name` is the queue's cell name.
  FleetConnection(std::string url, std::string who, std::string queue_name, bool with_league_store);
  ~FleetConnection();
  // Runs `work` on the connection (made first if needed); false when the database was lost.
  bool run(const std::function<void(FixtureQueue&, LeagueStore*)>& work);

 private:
  std::string url_, who_, queue_name_;
  bool with_store_;
  bool paused_ = false;
  bool connected_once_ = false;
  std::unique_ptr<FixtureQueue> queue_;
  std::unique_ptr<LeagueStore> store_;
};

}  // namespace olympics::selfplay
