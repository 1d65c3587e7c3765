#include "sqlite_results_store.h"

#include <stdexcept>

#include "results_schema.h"

namespace olympics::server {
namespace {

// A prepared statement that finalizes itself.
class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql) : db_(db) {
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt_, nullptr) != SQLITE_OK)
      throw std::runtime_error(std::string("results store: ") + sqlite3_errmsg(db));
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement& bind(int i, const std::string& v) {
    sqlite3_bind_text(stmt_, i, v.c_str(), -1, SQLITE_TRANSIENT);
    return *this;
  }
  Statement& bind(int i, std::int64_t v) {
    sqlite3_bind_int64(stmt_, i, v);
    return *this;
  }
  Statement& bind(int i, double v) {
    sqlite3_bind_double(stmt_, i, v);
    return *this;
  }
  bool step() {
    int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    throw std::runtime_error(std::string("results store: ") + sqlite3_errmsg(db_));
  }
  std::string text(int col) const {
    auto* t = sqlite3_column_text(stmt_, col);
    return t ? reinterpret_cast<const char*>(t) : "";
  }
  std::int64_t integer(int col) const { return sqlite3_column_int64(stmt_, col); }
  double real(int col) const { return sqlite3_column_double(stmt_, col); }

 private:
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

}  // namespace

SqliteResultsStore::SqliteResultsStore(const std::string& path) : path_(path) {
  if (sqlite3_open_v2(path.c_str(), &db_,
                      SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX,
                      nullptr) != SQLITE_OK) {
    std::string why = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    throw std::runtime_error("cannot open results database " + path + ": " + why +
                             " (check that the folder exists and is writable)");
  }
  sqlite3_busy_timeout(db_, 5000);  // several servers may share one file
  exec("PRAGMA journal_mode=WAL");
  exec(kResultsSchema);
}

SqliteResultsStore::~SqliteResultsStore() { sqlite3_close(db_); }

void SqliteResultsStore::exec(const char* sql) {
  char* error = nullptr;
  if (sqlite3_exec(db_, sql, nullptr, nullptr, &error) != SQLITE_OK) {
    std::string why = error ? error : "unknown error";
    sqlite3_free(error);
    throw std::runtime_error("results store " + path_ + ": " + why);
  }
}

void SqliteResultsStore::record(const StoredMatch& m) {
  std::lock_guard lock(mutex_);
  exec("BEGIN IMMEDIATE");
  try {
    Statement(db_, "INSERT INTO matches VALUES (?1,?2,?3,?4,?5,?6,?7,?8,?9,?10,?11,?12,?13,?14)")
        .bind(1, m.match_id)
        .bind(2, m.server_id)
        .bind(3, m.server_version)
        .bind(4, m.sport)
        .bind(5, m.mode)
        .bind(6, m.seed)
        .bind(7, std::int64_t{m.realtime})
        .bind(8, std::int64_t{m.ticks})
        .bind(9, m.wall_time_s)
        .bind(10, m.reason)
        .bind(11, std::int64_t{m.winner_team})
        .bind(12, scores_to_text(m.scores))
        .bind(13, m.info)
        .bind(14, m.finished_at_unix)
        .step();
    for (const auto& p : m.participants)
      Statement(db_, "INSERT INTO participants VALUES (?1,?2,?3,?4,?5,?6)")
          .bind(1, m.match_id)
          .bind(2, std::int64_t{p.slot})
          .bind(3, std::int64_t{p.team})
          .bind(4, p.agent)
          .bind(5, p.policy)
          .bind(6, p.policy_version)
          .step();
    exec("COMMIT");
  } catch (...) {
    exec("ROLLBACK");
    throw;
  }
}

std::vector<StoredMatch> SqliteResultsStore::query_matches(const std::string& where,
                                                           const std::vector<std::string>& args,
                                                           int limit) {
  std::lock_guard lock(mutex_);
  Statement q(db_,
              "SELECT match_id, server_id, server_version, sport, mode, seed, realtime, ticks, "
              "wall_time_s, reason, winner_team, scores, info, finished_at_unix FROM matches " +
                  where + " ORDER BY finished_at_unix DESC, rowid DESC LIMIT " +
                  std::to_string(limit));
  for (size_t i = 0; i < args.size(); ++i) q.bind(static_cast<int>(i) + 1, args[i]);
  std::vector<StoredMatch> out;
  while (q.step()) {
    StoredMatch m;
    m.match_id = q.text(0), m.server_id = q.text(1), m.server_version = q.text(2);
    m.sport = q.text(3), m.mode = q.text(4), m.seed = q.integer(5), m.realtime = q.integer(6) != 0;
    m.ticks = static_cast<int>(q.integer(7)), m.wall_time_s = q.real(8), m.reason = q.text(9);
    m.winner_team = static_cast<int>(q.integer(10)), m.scores = scores_from_text(q.text(11));
    m.info = q.text(12), m.finished_at_unix = q.integer(13);
    out.push_back(std::move(m));
  }
  for (auto& m : out) {
    Statement p(db_,
                "SELECT slot, team, agent, policy, policy_version FROM participants "
                "WHERE match_id = ?1 ORDER BY slot");
    p.bind(1, m.match_id);
    while (p.step())
      m.participants.push_back({static_cast<int>(p.integer(0)), static_cast<int>(p.integer(1)),
                                p.text(2), p.text(3), p.text(4)});
  }
  return out;
}

std::vector<StoredMatch> SqliteResultsStore::recent(int limit, const std::string& sport) {
  if (sport.empty()) return query_matches("", {}, limit);
  return query_matches("WHERE sport = ?1", {sport}, limit);
}

std::optional<StoredMatch> SqliteResultsStore::find(const std::string& match_id) {
  auto rows = query_matches("WHERE match_id = ?1", {match_id}, 1);
  if (rows.empty()) return std::nullopt;
  return rows.front();
}

}  // namespace olympics::server
