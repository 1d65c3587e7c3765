#include "fixture_queue.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "auth.h"
#include "sql_database.h"

namespace olympics::selfplay {
namespace {

// PostgreSQL only: SQLite has no row locks to skip, and one machine needs no queue.
constexpr const char* kSchema = R"sql(
CREATE TABLE IF NOT EXISTS fleet_tournaments (
  tournament TEXT PRIMARY KEY, secret_fingerprint TEXT NOT NULL,
  queued_at TIMESTAMPTZ NOT NULL DEFAULT now(), finished BOOLEAN NOT NULL DEFAULT false);
CREATE TABLE IF NOT EXISTS fleet_queue (
  tournament TEXT NOT NULL, idx INTEGER NOT NULL, state TEXT NOT NULL DEFAULT 'queued',
  cell TEXT NOT NULL DEFAULT '', lease_until TIMESTAMPTZ, leases INTEGER NOT NULL DEFAULT 0,
  refused TEXT NOT NULL DEFAULT '', PRIMARY KEY (tournament, idx));
CREATE INDEX IF NOT EXISTS fleet_queue_open ON fleet_queue (tournament, state, idx);
CREATE TABLE IF NOT EXISTS fleet_results (
  tournament TEXT NOT NULL, idx INTEGER NOT NULL, fixture_id TEXT NOT NULL, match_id TEXT NOT NULL,
  cell TEXT NOT NULL, home_score DOUBLE PRECISION NOT NULL, reason TEXT NOT NULL,
  ticks INTEGER NOT NULL, stored_at TIMESTAMPTZ NOT NULL DEFAULT now(),
  places TEXT NOT NULL DEFAULT '', PRIMARY KEY (tournament, idx), UNIQUE (fixture_id));
CREATE TABLE IF NOT EXISTS fleet_snapshots (
  tournament TEXT NOT NULL, policy TEXT NOT NULL, bytes BYTEA NOT NULL,
  stored_at TIMESTAMPTZ NOT NULL DEFAULT now(), PRIMARY KEY (tournament, policy));
)sql";
// A ranked fixture's places (JSON array, '' for a two-team game): added since the first schema.
constexpr const char* kPlacesColumn = "TEXT NOT NULL DEFAULT ''";

constexpr int kDone = static_cast<int>(GameStatus::Done);

std::string hex(const std::uint8_t* bytes, int size) {
  std::string out;
  char two[3];
  for (int i = 0; i < size; ++i) {
    std::snprintf(two, sizeof two, "%02x", bytes[i]);
    out += two;
  }
  return out;
}

}  // namespace

std::string secret_fingerprint(const std::string& secret_file) {
  auto auth = protocol::load_secret(secret_file);
  if (!auth) return "";
  std::string text = "olympics fleet queue fingerprint";
  std::vector<std::uint8_t> bytes(text.begin(), text.end());
  bytes.resize(bytes.size() + protocol::kSignatureBytes);
  auth->sign("OLY_FLEET_QUEUE", bytes.data(), static_cast<int>(bytes.size()));
  return hex(bytes.data() + bytes.size() - protocol::kMacBytes, 8);  // the MAC, not the freshness
}

std::string with_fleet_timeouts(const std::string& url) {
  std::string out = url;
  if (url.rfind("postgresql://", 0) != 0 && url.rfind("postgres://", 0) != 0) return out;
  for (std::string setting :
       {"connect_timeout=3", "keepalives=1", "keepalives_idle=2", "keepalives_interval=1",
        "keepalives_count=2", "tcp_user_timeout=4000"}) {
    if (out.find(setting.substr(0, setting.find('=') + 1)) != std::string::npos) continue;
    out.push_back(out.find('?') == std::string::npos ? '?' : '&');
    out.append(setting);
  }
  return out;
}

FixtureQueue::FixtureQueue(const std::string& url, std::string cell) : cell_(std::move(cell)) {
  if (url.rfind("postgresql://", 0) != 0 && url.rfind("postgres://", 0) != 0)
    throw std::invalid_argument(
        "the fleet's queue lives in PostgreSQL; --db " + url +
        " is not a postgresql:// URL (one machine needs no queue: olympics-league run --db FILE)");
  db_ = sql::open_sql_database(url);
  db_->create_schema(kSchema);
  sql::add_column_if_missing(*db_, "fleet_results", "places", kPlacesColumn);
}

FixtureQueue::~FixtureQueue() = default;

void FixtureQueue::queue_pending(const std::string& tournament, const std::string& fingerprint) {
  // Both idempotent, so no transaction of its own: it runs inside the round lock's.
  db_->query(
      "INSERT INTO fleet_tournaments (tournament, secret_fingerprint) VALUES ($1, $2) "
      "ON CONFLICT (tournament) DO NOTHING",
      {tournament, fingerprint});
  db_->query(
      "INSERT INTO fleet_queue (tournament, idx) SELECT tournament, idx FROM games "
      "WHERE tournament = $1 AND status <> $2 ON CONFLICT (tournament, idx) DO NOTHING",
      {tournament, std::to_string(kDone)});
}

std::vector<int> FixtureQueue::lease(const std::string& tournament, const std::string& fingerprint,
                                     int count, double lease_s) {
  auto stored = db_->query("SELECT secret_fingerprint FROM fleet_tournaments WHERE tournament = $1",
                           {tournament});
  if (stored.empty())
    throw std::invalid_argument(
        "tournament \"" + tournament + "\" is not queued in " + db_->describe() +
        "; queue it first: olympics-league run --fleet --db URL --name " + tournament + " ...");
  if (stored[0][0] != fingerprint) {
    auto shown = [](const std::string& f) { return f.empty() ? std::string("none") : f; };
    throw std::invalid_argument(
        "the queue refuses cell " + cell_ + ": its secret (fingerprint " + shown(fingerprint) +
        ") is not the one tournament \"" + tournament + "\" was queued with (fingerprint " +
        shown(stored[0][0]) +
        "); give the cell the deployment's secret file (--secret or OLYMPICS_SECRET_FILE)");
  }
  std::vector<int> out;
  for (const auto& r :
       db_->query("WITH picked AS (SELECT idx FROM fleet_queue WHERE tournament = $1 AND "
                  "(state = 'queued' OR (state = 'leased' AND lease_until < now())) ORDER BY idx "
                  "LIMIT $4 FOR UPDATE SKIP LOCKED) "
                  "UPDATE fleet_queue q SET state = 'leased', cell = $2, leases = q.leases + 1, "
                  "lease_until = now() + $3::double precision * interval '1 second' FROM picked "
                  "WHERE q.tournament = $1 AND q.idx = picked.idx RETURNING q.idx",
                  {tournament, cell_, sql::exact_text(lease_s), std::to_string(count)}))
    out.push_back(std::stoi(r[0]));
  std::sort(out.begin(), out.end());
  return out;
}

int FixtureQueue::renew(const std::string& tournament, double lease_s) {
  return static_cast<int>(
      db_->query("UPDATE fleet_queue SET lease_until = now() + $3::double precision * "
                 "interval '1 second' WHERE tournament = $1 AND cell = $2 AND state = 'leased' "
                 "RETURNING idx",
                 {tournament, cell_, sql::exact_text(lease_s)})
          .size());
}

bool FixtureQueue::store_result(const std::string& tournament, const FinishedFixture& r) {
  bool first = false;
  const std::string fixture_id = tournament + "-g" + std::to_string(r.index);
  db_->transaction([&] {
    first = !db_->query(
                    "INSERT INTO fleet_results (tournament, idx, fixture_id, match_id, cell, "
                    "home_score, reason, ticks, places) VALUES ($1,$2,$3,$4,$5,$6,$7,$8,$9) "
                    "ON CONFLICT DO NOTHING RETURNING idx",
                    {tournament, std::to_string(r.index), fixture_id, r.match_id, cell_,
                     sql::exact_text(r.home_score), r.reason, std::to_string(r.ticks),
                     int_list_text(r.places)})
                 .empty();
    if (first)
      db_->query(
          "UPDATE games SET status = $3, request_id = $4, server_id = $5, match_id = $6, "
          "home_score = $7, reason = $8, ticks = $9, places = $10 "
          "WHERE tournament = $1 AND idx = $2",
          {tournament, std::to_string(r.index), std::to_string(kDone), fixture_id, cell_,
           r.match_id, sql::exact_text(r.home_score), r.reason, std::to_string(r.ticks),
           int_list_text(r.places)});
    db_->query(
        "UPDATE fleet_queue SET state = 'done', lease_until = NULL "
        "WHERE tournament = $1 AND idx = $2",
        {tournament, std::to_string(r.index)});
  });
  return first;
}

void FixtureQueue::give_back(const std::string& tournament, const std::string& why) {
  db_->query(
      "UPDATE fleet_queue SET state = 'queued', lease_until = NULL, cell = '', refused = $3 "
      "WHERE tournament = $1 AND cell = $2 AND state = 'leased'",
      {tournament, cell_, cell_ + ": " + why});
}

int FixtureQueue::unfinished(const std::string& tournament) {
  return std::stoi(
      db_->query("SELECT count(*) FROM fleet_queue WHERE tournament = $1 AND "
                 "state <> 'done'",
                 {tournament})[0][0]);
}

std::vector<std::string> FixtureQueue::refusals(const std::string& tournament) {
  std::vector<std::string> out;
  for (const auto& r : db_->query("SELECT DISTINCT refused FROM fleet_queue WHERE tournament = $1 "
                                  "AND refused <> '' AND state <> 'done' ORDER BY refused",
                                  {tournament}))
    out.push_back(r[0]);
  return out;
}

void FixtureQueue::with_round_lock(const std::string& tournament,
                                   const std::function<void()>& work) {
  db_->transaction([&] {
    db_->query("SELECT pg_advisory_xact_lock(hashtext('olympics-fleet-' || $1))", {tournament});
    work();
  });
}

std::vector<std::string> FixtureQueue::active_tournaments() {
  std::vector<std::string> out;
  for (const auto& r : db_->query("SELECT tournament FROM fleet_tournaments WHERE NOT finished "
                                  "ORDER BY queued_at, tournament"))
    out.push_back(r[0]);
  return out;
}

bool FixtureQueue::finished(const std::string& tournament) {
  auto rows =
      db_->query("SELECT finished FROM fleet_tournaments WHERE tournament = $1", {tournament});
  return !rows.empty() && (rows[0][0] == "t" || rows[0][0] == "true");
}

void FixtureQueue::mark_finished(const std::string& tournament) {
  db_->query("UPDATE fleet_tournaments SET finished = true WHERE tournament = $1", {tournament});
}

void FixtureQueue::store_snapshot(const std::string& tournament, const std::string& policy,
                                  const std::string& bytes) {
  // bytea's hex input form, so that the bytes travel as text like every other value.
  db_->query(
      "INSERT INTO fleet_snapshots (tournament, policy, bytes) VALUES ($1, $2, $3::bytea) "
      "ON CONFLICT (tournament, policy) DO NOTHING",
      {tournament, policy,
       "\\x" + hex(reinterpret_cast<const std::uint8_t*>(bytes.data()),
                   static_cast<int>(bytes.size()))});
}

std::vector<std::string> FixtureQueue::snapshot_policies(const std::string& tournament) {
  std::vector<std::string> out;
  for (const auto& r :
       db_->query("SELECT policy FROM fleet_snapshots WHERE tournament = $1 ORDER BY policy",
                  {tournament}))
    out.push_back(r[0]);
  return out;
}

std::optional<std::string> FixtureQueue::snapshot(const std::string& tournament,
                                                  const std::string& policy) {
  auto rows = db_->query(
      "SELECT encode(bytes, 'hex') FROM fleet_snapshots WHERE tournament = $1 AND policy = $2",
      {tournament, policy});
  if (rows.empty()) return std::nullopt;
  const std::string& text = rows[0][0];
  std::string bytes(text.size() / 2, '\0');
  for (size_t i = 0; i < bytes.size(); ++i)
    bytes[i] = static_cast<char>(std::stoi(text.substr(2 * i, 2), nullptr, 16));
  return bytes;
}

bool FixtureQueue::alive() {
  try {
    db_->query("SELECT 1");
    return true;
  } catch (const std::runtime_error&) {
    return false;
  }
}

}  // namespace olympics::selfplay
