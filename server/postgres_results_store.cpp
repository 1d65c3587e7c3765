#include "postgres_results_store.h"

#include <memory>
#include <regex>
#include <stdexcept>

#include "results_schema.h"

namespace olympics::server {

// A PGresult that clears itself, with the checks every call needs.
struct PostgresResultsStore::Result {
  std::unique_ptr<PGresult, decltype(&PQclear)> r{nullptr, &PQclear};
  int rows() const { return PQntuples(r.get()); }
};

namespace {
// One row of a result, in the shape match_from_row() reads.
struct RowView {
  PGresult* r;
  int row;
  std::string text(int col) const { return PQgetvalue(r, row, col); }
  std::int64_t integer(int col) const { return std::stoll(text(col)); }
  double real(int col) const { return std::stod(text(col)); }
};
}  // namespace

PostgresResultsStore::PostgresResultsStore(const std::string& url)
    : shown_url_(std::regex_replace(url, std::regex(":[^:@/]*@"), ":***@")) {
  conn_ = PQconnectdb(url.c_str());
  if (PQstatus(conn_) != CONNECTION_OK) {
    std::string why = PQerrorMessage(conn_);
    PQfinish(conn_);
    throw std::runtime_error("cannot connect to results database " + shown_url_ + ": " + why +
                             "(check the URL, that the server runs and that the role may log in)");
  }
  exec("SET client_min_messages TO WARNING");  // quiet "already exists" notices
  exec(kResultsSchema);
}

PostgresResultsStore::~PostgresResultsStore() { PQfinish(conn_); }

PostgresResultsStore::Result PostgresResultsStore::exec(const std::string& sql,
                                                        const std::vector<std::string>& params) {
  std::vector<const char*> values;
  for (const auto& p : params) values.push_back(p.c_str());
  Result res;
  if (params.empty())
    res.r.reset(PQexec(conn_, sql.c_str()));
  else
    res.r.reset(PQexecParams(conn_, sql.c_str(), static_cast<int>(values.size()), nullptr,
                             values.data(), nullptr, nullptr, 0));
  auto status = PQresultStatus(res.r.get());
  if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK)
    throw std::runtime_error("results store " + shown_url_ + ": " + PQerrorMessage(conn_));
  return res;
}

void PostgresResultsStore::record(const StoredMatch& m) {
  std::lock_guard lock(mutex_);
  exec("BEGIN");
  try {
    exec("INSERT INTO matches VALUES ($1,$2,$3,$4,$5,$6,$7,$8,$9,$10,$11,$12,$13,$14)",
         {m.match_id, m.server_id, m.server_version, m.sport, m.mode, std::to_string(m.seed),
          std::to_string(m.realtime ? 1 : 0), std::to_string(m.ticks),
          std::to_string(m.wall_time_s), m.reason, std::to_string(m.winner_team),
          scores_to_text(m.scores), m.info, std::to_string(m.finished_at_unix)});
    for (const auto& p : m.participants)
      exec("INSERT INTO participants VALUES ($1,$2,$3,$4,$5,$6)",
           {m.match_id, std::to_string(p.slot), std::to_string(p.team), p.agent, p.policy,
            p.policy_version});
    exec("COMMIT");
  } catch (...) {
    exec("ROLLBACK");
    throw;
  }
}

std::vector<StoredMatch> PostgresResultsStore::select(const std::string& column,
                                                      const std::string& value, int limit) {
  std::lock_guard lock(mutex_);
  const std::string where = column.empty() ? "" : "WHERE " + column + " = $1";
  Result q = exec(kSelectMatches + where + " ORDER BY finished_at_unix DESC, match_id DESC LIMIT " +
                      std::to_string(limit),
                  column.empty() ? std::vector<std::string>{} : std::vector<std::string>{value});
  std::vector<StoredMatch> out;
  for (int i = 0; i < q.rows(); ++i) {
    StoredMatch m = match_from_row(RowView{q.r.get(), i});
    Result p =
        exec(std::string(kSelectParticipants) + "WHERE match_id = $1 ORDER BY slot", {m.match_id});
    for (int k = 0; k < p.rows(); ++k)
      m.participants.push_back(participant_from_row(RowView{p.r.get(), k}));
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace olympics::server
