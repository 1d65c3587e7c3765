#include "results_store.h"

#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "results_schema.h"
#include "sql_database.h"

namespace olympics::server {
namespace {

// A row of text values, as the SQL layer returns it.
struct TextRow {
  const sql::SqlDatabase::Row& r;
  std::string text(int c) const { return r[c]; }
  std::int64_t integer(int c) const { return std::stoll(r[c]); }
  double real(int c) const { return std::stod(r[c]); }
};

// Columns in kSelectMatches' and kSelectParticipants' order.
StoredMatch match_from_row(const TextRow& q) {
  StoredMatch m;
  m.match_id = q.text(0), m.server_id = q.text(1), m.server_version = q.text(2);
  m.sport = q.text(3), m.mode = q.text(4), m.seed = q.integer(5), m.realtime = q.integer(6) != 0;
  m.ticks = static_cast<int>(q.integer(7)), m.wall_time_s = q.real(8), m.reason = q.text(9);
  m.winner_team = static_cast<int>(q.integer(10)), m.scores = scores_from_text(q.text(11));
  m.info = q.text(12), m.finished_at_unix = q.integer(13), m.options = q.text(14);
  return m;
}

StoredParticipant participant_from_row(const TextRow& p) {
  return {static_cast<int>(p.integer(0)), static_cast<int>(p.integer(1)), p.text(2), p.text(3),
          p.text(4)};
}

}  // namespace

// A result is committed atomically and survives a crash of the process; in SQLite an fsync per
// match (against power loss) cost the stepping threads ~5% of their throughput.
ResultsStore::ResultsStore(const std::string& location)
    : db_(sql::open_sql_database(location, sql::Durability::ProcessCrash)) {
  db_->create_schema(kResultsSchema);
  for (const auto& [column, definition] : kResultsAddedColumns)
    sql::add_column_if_missing(*db_, "matches", column, definition);
}

ResultsStore::~ResultsStore() = default;

std::unique_ptr<ResultsStore> open_results_store(const std::string& location) {
  return std::make_unique<ResultsStore>(location);
}

std::string ResultsStore::describe() const { return db_->describe(); }

void ResultsStore::record(const StoredMatch& m) {
  std::lock_guard lock(mutex_);
  db_->transaction([&] {
    db_->query(
        "INSERT INTO matches (match_id, server_id, server_version, sport, mode, seed, "
        "realtime, ticks, wall_time_s, reason, winner_team, scores, info, "
        "finished_at_unix, options) VALUES ($1,$2,$3,$4,$5,$6,$7,$8,$9,$10,$11,$12,$13,$14,"
        "$15)",
        {m.match_id, m.server_id, m.server_version, m.sport, m.mode, std::to_string(m.seed),
         m.realtime ? "1" : "0", std::to_string(m.ticks), sql::exact_text(m.wall_time_s), m.reason,
         std::to_string(m.winner_team), scores_to_text(m.scores), m.info,
         std::to_string(m.finished_at_unix), m.options});
    for (const auto& p : m.participants)
      db_->query("INSERT INTO participants VALUES ($1,$2,$3,$4,$5,$6)",
                 {m.match_id, std::to_string(p.slot), std::to_string(p.team), p.agent, p.policy,
                  p.policy_version});
    db_->query("DELETE FROM matches_in_progress WHERE match_id = $1", {m.match_id});
  });
}

namespace {

std::string players_json(const std::vector<StoredParticipant>& players) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : players)
    out.push_back({{"slot", p.slot},
                   {"team", p.team},
                   {"agent", p.agent},
                   {"policy", p.policy},
                   {"policy_version", p.policy_version}});
  return out.dump();
}

}  // namespace

void ResultsStore::note_in_progress(const StoredMatch& m) {
  std::lock_guard lock(mutex_);
  db_->query(
      "INSERT INTO matches_in_progress (match_id, server_id, sport, mode, seed, realtime, "
      "options, participants, created_at_unix) VALUES ($1,$2,$3,$4,$5,$6,$7,$8,$9)",
      {m.match_id, m.server_id, m.sport, m.mode, std::to_string(m.seed), m.realtime ? "1" : "0",
       m.options, players_json(m.participants), std::to_string(m.finished_at_unix)});
}

void ResultsStore::note_players(const std::string& match_id,
                                const std::vector<StoredParticipant>& players) {
  std::lock_guard lock(mutex_);
  db_->query("UPDATE matches_in_progress SET participants = $2 WHERE match_id = $1",
             {match_id, players_json(players)});
}

int ResultsStore::abort_unfinished(const std::string& server_id, std::int64_t now_unix) {
  std::vector<StoredMatch> left;
  {
    std::lock_guard lock(mutex_);
    for (const auto& r :
         db_->query("SELECT match_id, sport, mode, seed, realtime, options, participants FROM "
                    "matches_in_progress WHERE server_id = $1 ORDER BY created_at_unix, match_id",
                    {server_id})) {
      StoredMatch m;
      m.match_id = r[0], m.server_id = server_id, m.server_version = "?";
      m.sport = r[1], m.mode = r[2], m.seed = std::stoll(r[3]), m.realtime = r[4] == "1";
      m.options = r[5];
      m.reason = "aborted: server " + server_id + " stopped before the match ended";
      m.winner_team = -1;
      m.info = "{}";
      m.finished_at_unix = now_unix;
      for (const auto& p : nlohmann::json::parse(r[6], nullptr, false))
        if (p.is_object())
          m.participants.push_back({p.value("slot", 0), p.value("team", 0), p.value("agent", ""),
                                    p.value("policy", ""), p.value("policy_version", "")});
      left.push_back(std::move(m));
    }
  }
  for (const auto& m : left) record(m);
  return static_cast<int>(left.size());
}

std::vector<StoredMatch> ResultsStore::select(const std::string& column, const std::string& value,
                                              int limit) {
  std::lock_guard lock(mutex_);
  const std::string where = column.empty() ? "" : "WHERE " + column + " = $1";
  auto rows =
      db_->query(kSelectMatches + where + " ORDER BY finished_at_unix DESC, match_id DESC LIMIT " +
                     std::to_string(limit),
                 column.empty() ? std::vector<std::string>{} : std::vector<std::string>{value});
  std::vector<StoredMatch> out;
  for (const auto& r : rows) {
    StoredMatch m = match_from_row(TextRow{r});
    for (const auto& p : db_->query(
             std::string(kSelectParticipants) + "WHERE match_id = $1 ORDER BY slot", {m.match_id}))
      m.participants.push_back(participant_from_row(TextRow{p}));
    out.push_back(std::move(m));
  }
  return out;
}

std::vector<StoredMatch> ResultsStore::recent(int limit, const std::string& sport) {
  return select(sport.empty() ? "" : "sport", sport, limit);
}

std::optional<StoredMatch> ResultsStore::find(const std::string& match_id) {
  auto rows = select("match_id", match_id, 1);
  if (rows.empty()) return std::nullopt;
  return rows.front();
}

std::string scores_to_text(const std::vector<double>& scores) {
  std::ostringstream out;
  out.precision(17);
  for (size_t i = 0; i < scores.size(); ++i) out << (i ? "," : "") << scores[i];
  return out.str();
}

std::vector<double> scores_from_text(const std::string& text) {
  std::vector<double> out;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(std::stod(item));
  return out;
}

}  // namespace olympics::server
