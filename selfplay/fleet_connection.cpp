#include "fleet_connection.h"

#include <cstdio>
#include <stdexcept>

namespace olympics::selfplay {

FleetConnection::FleetConnection(std::string url, std::string who, std::string queue_name,
                                 bool with_league_store)
    : url_(with_fleet_timeouts(url)),
      who_(std::move(who)),
      queue_name_(std::move(queue_name)),
      with_store_(with_league_store) {}

FleetConnection::~FleetConnection() = default;

bool FleetConnection::run(const std::function<void(FixtureQueue&, LeagueStore*)>& work) {
  try {
    if (!queue_) {
      queue_ = std::make_unique<FixtureQueue>(url_, queue_name_);
      if (with_store_) store_ = std::make_unique<LeagueStore>(url_);
    }
    work(*queue_, store_.get());
  } catch (const std::runtime_error& e) {
    // The database answering "no" (credentials, a missing database) will not change by waiting.
    const std::string why = e.what();
    for (const char* refusal :
         {"password authentication failed", "no pg_hba.conf entry", "does not exist"})
      if (why.find(refusal) != std::string::npos)
        throw std::invalid_argument("the database refuses " + who_ + ": " + why);
    if (!paused_ && !connected_once_)
      std::fprintf(stderr, "%s: cannot reach the database (%s); trying again\n", who_.c_str(),
                   e.what());
    else if (!paused_)
      std::fprintf(stderr,
                   "%s: lost the database (%s); paused: no new fixtures, finished results "
                   "kept until it is back\n",
                   who_.c_str(), e.what());
    paused_ = true;
    queue_.reset();
    store_.reset();
    return false;
  }
  if (paused_) std::fprintf(stderr, "%s: database back; going on\n", who_.c_str());
  paused_ = false;
  connected_once_ = true;
  return true;
}

}  // namespace olympics::selfplay
