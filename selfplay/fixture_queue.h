// The league's work queue across cells (a fleet), in PostgreSQL: a tournament's games are
// fixtures, rows a cell leases in batches (SELECT ... FOR UPDATE SKIP LOCKED) for a time it
// renews while it plays them; a lease that runs out returns its unfinished fixtures to the queue.
// Results are stored once per fixture (an upsert keyed by the fixture's id, "<tournament>-g<idx>"),
// into the league's own `games` rows, so `olympics-league table` and ratings work as on one host.
// The queue also checks the deployment's secret: a cell whose secret differs from the one the
// tournament was queued with leases nothing and is told why.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "league_store.h"

namespace olympics::sql {
class SqlDatabase;
}

namespace olympics::selfplay {

// A short, non-secret fingerprint of the deployment's secret file (HMAC under its client key of a
// fixed text); "" without a secret. Equal fingerprints: the same secret.
std::string secret_fingerprint(const std::string& secret_file);

// The URL with libpq settings that make a lost database show up in seconds, not minutes
// (connect timeout, TCP keepalives, a TCP user timeout), unless the URL sets them itself.
std::string with_fleet_timeouts(const std::string& postgres_url);

struct FinishedFixture {
  int index = 0;
  std::string match_id;  // the server's match id (the fixture's id is <tournament>-g<index>)
  double home_score = 0;
  std::string reason;
  int ticks = 0;
  std::vector<int> places =
      {};  // a ranked fixture's places per team (Game::places); empty otherwise
};

class FixtureQueue {
 public:
  // `url` must be a postgresql:// URL (throws saying so otherwise, or what to check when it
  // cannot connect). Makes the queue's tables if missing.
  FixtureQueue(const std::string& url, std::string cell);
  ~FixtureQueue();

  // Records the tournament's secret fingerprint (first queueing wins) and queues every game of
  // the league's `games` rows that is not done yet (idempotent).
  void queue_pending(const std::string& tournament, const std::string& fingerprint);
  // Leases up to `count` queued fixtures (or ones whose lease ran out) for `lease_s`; their game
  // indices in order. Throws std::invalid_argument when the cell's secret fingerprint is not the
  // tournament's, or the tournament was never queued.
  std::vector<int> lease(const std::string& tournament, const std::string& fingerprint, int count,
                         double lease_s);
  // Extends this cell's leases of the tournament; how many it still holds.
  int renew(const std::string& tournament, double lease_s);
  // Stores a result once: false when the fixture already had one (played twice: the first counts).
  bool store_result(const std::string& tournament, const FinishedFixture& result);
  // Gives this cell's unfinished leases back at once, noting why (a sport it does not host).
  void give_back(const std::string& tournament, const std::string& why);
  // Fixtures of the tournament not done yet; and refusals noted on them ("cell: why").
  int unfinished(const std::string& tournament);
  std::vector<std::string> refusals(const std::string& tournament);
  // Runs `work` holding the tournament's advancement lock (one cell adds the next round).
  void with_round_lock(const std::string& tournament, const std::function<void()>& work);
  // Tournaments queued and not finished, oldest first; whether one is finished; mark it so.
  std::vector<std::string> active_tournaments();
  bool finished(const std::string& tournament);
  void mark_finished(const std::string& tournament);
  // Snapshots (mlp:FILE entrants) travel through the database, so that a cell needs no shared
  // folder: the scheduler stores each file's bytes once, when its entrant joins; a cell copies
  // them to a cache of its own. Stored once per (tournament, policy): the first copy counts.
  void store_snapshot(const std::string& tournament, const std::string& policy,
                      const std::string& bytes);
  std::vector<std::string> snapshot_policies(const std::string& tournament);
  std::optional<std::string> snapshot(const std::string& tournament, const std::string& policy);
  // Whether the connection still answers (a cheap query).
  bool alive();

  const std::string& cell() const { return cell_; }

 private:
  std::unique_ptr<sql::SqlDatabase> db_;
  std::string cell_;
};

}  // namespace olympics::selfplay
