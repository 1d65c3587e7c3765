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
  // WAL with synchronous=NORMAL: a commit is atomic and survives a crash of the process; only a
  // power loss can drop the last commits. A full fsync per match cost the stepping thread ~5%.
  exec("PRAGMA synchronous=NORMAL");
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

std::vector<StoredMatch> SqliteResultsStore::select(const std::string& column,
                                                    const std::string& value, int limit) {
  std::lock_guard lock(mutex_);
  const std::string where = column.empty() ? "" : "WHERE " + column + " = ?1";
  Statement q(db_, kSelectMatches + where + " ORDER BY finished_at_unix DESC, rowid DESC LIMIT " +
                       std::to_string(limit));
  if (!column.empty()) q.bind(1, value);
  std::vector<StoredMatch> out;
  while (q.step()) out.push_back(match_from_row(q));
  for (auto& m : out) {
    Statement p(db_, std::string(kSelectParticipants) + "WHERE match_id = ?1 ORDER BY slot");
    p.bind(1, m.match_id);
    while (p.step()) m.participants.push_back(participant_from_row(p));
  }
  return out;
}

}  // namespace olympics::server
