// Where finished matches are kept: SQLite by default (a file path), PostgreSQL by URL
// (postgresql://...). One schema for both (docs/results.md).
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace olympics::sql {
class SqlDatabase;
}

namespace olympics::server {

struct StoredParticipant {
  int slot = 0;
  int team = 0;
  std::string agent;
  std::string policy;
  std::string policy_version;
};

struct StoredMatch {
  std::string match_id;
  std::string server_id;
  std::string server_version;
  std::string sport;
  std::string mode;
  std::int64_t seed = 0;
  bool realtime = false;
  int ticks = 0;
  double wall_time_s = 0;
  std::string reason;
  int winner_team = -1;
  std::vector<double> scores;  // per team
  std::string info;            // JSON
  std::string options = "{}";  // the sport's settings in force, JSON
  std::int64_t finished_at_unix = 0;
  std::vector<StoredParticipant> participants;
};

class ResultsStore {
 public:
  explicit ResultsStore(const std::string& location);  // see open_results_store
  ~ResultsStore();
  ResultsStore(const ResultsStore&) = delete;
  ResultsStore& operator=(const ResultsStore&) = delete;

  // Writes one match and its participants atomically, and drops its in-progress note; a match id
  // already stored is an error.
  void record(const StoredMatch& match);
  // A match the server took on (`match` without its end: id, server, sport, mode, seed, realtime,
  // options), so that a crash leaves a trace; then its players, once it starts.
  void note_in_progress(const StoredMatch& match);
  void note_players(const std::string& match_id, const std::vector<StoredParticipant>& players);
  // Matches `server_id` left unfinished (a crash): recorded as "aborted", with no winner; how
  // many there were.
  int abort_unfinished(const std::string& server_id, std::int64_t now_unix);
  // Most recent first; `sport` empty = all sports.
  std::vector<StoredMatch> recent(int limit, const std::string& sport = "");
  std::optional<StoredMatch> find(const std::string& match_id);
  std::string describe() const;  // "sqlite:/path" or the URL without password

 private:
  // Matches (with participants), newest first, where `column` equals `value` (no filter when
  // column is empty). Column names come from this class only, never from users.
  std::vector<StoredMatch> select(const std::string& column, const std::string& value, int limit);
  std::unique_ptr<olympics::sql::SqlDatabase> db_;
  std::mutex mutex_;  // one connection, shared by the worker threads
};

// "postgresql://..." or "postgres://..." -> PostgreSQL; anything else is a SQLite file path.
// Throws std::runtime_error with the reason and what to do when the store cannot be opened.
std::unique_ptr<ResultsStore> open_results_store(const std::string& location);

// Scores as the text stored in the scores column: "1.5,0".
std::string scores_to_text(const std::vector<double>& scores);
std::vector<double> scores_from_text(const std::string& text);

}  // namespace olympics::server
