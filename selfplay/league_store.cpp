#include "league_store.h"

#include <nlohmann/json.hpp>
#include <stdexcept>

namespace olympics::selfplay {
namespace {

constexpr const char* kSchema = R"sql(
CREATE TABLE IF NOT EXISTS tournaments (
  name TEXT PRIMARY KEY, format TEXT NOT NULL, sport TEXT NOT NULL, mode TEXT NOT NULL,
  seed INTEGER NOT NULL, time_limit_s REAL NOT NULL, entrants TEXT NOT NULL,
  options TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS games (
  tournament TEXT NOT NULL REFERENCES tournaments(name), idx INTEGER NOT NULL,
  round INTEGER NOT NULL, home INTEGER NOT NULL, away INTEGER NOT NULL, status INTEGER NOT NULL,
  attempt INTEGER NOT NULL, request_id TEXT NOT NULL, server_id TEXT NOT NULL,
  match_id TEXT NOT NULL, home_score REAL NOT NULL, reason TEXT NOT NULL, ticks INTEGER NOT NULL,
  PRIMARY KEY (tournament, idx));
)sql";

struct Stmt {
  Stmt(sqlite3* db, const char* sql) : db(db) {
    if (sqlite3_prepare_v2(db, sql, -1, &s, nullptr) != SQLITE_OK)
      throw std::runtime_error(std::string("league store: ") + sqlite3_errmsg(db));
  }
  ~Stmt() { sqlite3_finalize(s); }
  Stmt& text(int i, const std::string& v) {
    sqlite3_bind_text(s, i, v.c_str(), -1, SQLITE_TRANSIENT);
    return *this;
  }
  Stmt& num(int i, double v) {
    sqlite3_bind_double(s, i, v);
    return *this;
  }
  Stmt& integer(int i, std::int64_t v) {
    sqlite3_bind_int64(s, i, v);
    return *this;
  }
  bool step() {
    int rc = sqlite3_step(s);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    throw std::runtime_error(std::string("league store: ") + sqlite3_errmsg(db));
  }
  std::string col_text(int c) {
    auto* t = sqlite3_column_text(s, c);
    return t ? reinterpret_cast<const char*>(t) : "";
  }
  sqlite3* db;
  sqlite3_stmt* s = nullptr;
};

}  // namespace

LeagueStore::LeagueStore(const std::string& path) : path_(path) {
  if (sqlite3_open(path.c_str(), &db_) != SQLITE_OK) {
    std::string why = sqlite3_errmsg(db_);
    sqlite3_close(db_);
    throw std::runtime_error("cannot open league database " + path + ": " + why);
  }
  sqlite3_busy_timeout(db_, 5000);
  exec("PRAGMA journal_mode=WAL");
  exec("PRAGMA synchronous=FULL");  // every step survives a kill -9 and a power loss
  exec(kSchema);
}

LeagueStore::~LeagueStore() { sqlite3_close(db_); }

void LeagueStore::exec(const std::string& sql) {
  char* error = nullptr;
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &error) != SQLITE_OK) {
    std::string why = error ? error : "?";
    sqlite3_free(error);
    throw std::runtime_error("league store " + path_ + ": " + why);
  }
}

std::optional<TournamentSpec> LeagueStore::find_tournament(const std::string& name) {
  Stmt q(db_,
         "SELECT format, sport, mode, seed, time_limit_s, entrants, options FROM tournaments "
         "WHERE name = ?1");
  q.text(1, name);
  if (!q.step()) return std::nullopt;
  TournamentSpec t;
  t.name = name;
  t.format = q.col_text(0), t.sport = q.col_text(1), t.mode = q.col_text(2);
  t.seed = static_cast<std::uint64_t>(sqlite3_column_int64(q.s, 3));
  t.time_limit_s = sqlite3_column_double(q.s, 4);
  for (const auto& e : nlohmann::json::parse(q.col_text(5)))
    t.entrants.push_back({e.at("name"), e.at("policy"), e.at("seed")});
  t.options = q.col_text(6);
  return t;
}

std::vector<std::string> LeagueStore::tournament_names() {
  Stmt q(db_, "SELECT name FROM tournaments ORDER BY name");
  std::vector<std::string> out;
  while (q.step()) out.push_back(q.col_text(0));
  return out;
}

namespace {
std::string entrants_json(const TournamentSpec& t) {
  nlohmann::json entrants = nlohmann::json::array();
  for (const auto& e : t.entrants)
    entrants.push_back({{"name", e.name}, {"policy", e.policy}, {"seed", e.seed}});
  return entrants.dump();
}
}  // namespace

void LeagueStore::update_entrants(const TournamentSpec& t) {
  Stmt(db_, "UPDATE tournaments SET entrants = ?2 WHERE name = ?1")
      .text(1, t.name)
      .text(2, entrants_json(t))
      .step();
}

void LeagueStore::create_tournament(const TournamentSpec& t) {
  Stmt(db_, "INSERT INTO tournaments VALUES (?1,?2,?3,?4,?5,?6,?7,?8)")
      .text(1, t.name)
      .text(2, t.format)
      .text(3, t.sport)
      .text(4, t.mode)
      .integer(5, static_cast<std::int64_t>(t.seed))
      .num(6, t.time_limit_s)
      .text(7, entrants_json(t))
      .text(8, t.options.empty() ? "{}" : t.options)
      .step();
}

std::vector<Game> LeagueStore::games(const std::string& tournament) {
  Stmt q(db_,
         "SELECT idx, round, home, away, status, attempt, request_id, server_id, match_id, "
         "home_score, reason, ticks FROM games WHERE tournament = ?1 ORDER BY idx");
  q.text(1, tournament);
  std::vector<Game> out;
  while (q.step()) {
    Game g;
    g.index = sqlite3_column_int(q.s, 0), g.round = sqlite3_column_int(q.s, 1);
    g.home = sqlite3_column_int(q.s, 2), g.away = sqlite3_column_int(q.s, 3);
    g.status = static_cast<GameStatus>(sqlite3_column_int(q.s, 4));
    g.attempt = sqlite3_column_int(q.s, 5);
    g.request_id = q.col_text(6), g.server_id = q.col_text(7), g.match_id = q.col_text(8);
    g.home_score = sqlite3_column_double(q.s, 9), g.reason = q.col_text(10);
    g.ticks = sqlite3_column_int(q.s, 11);
    out.push_back(g);
  }
  return out;
}

void LeagueStore::add_games(const std::string& tournament, const std::vector<Game>& games) {
  exec("BEGIN IMMEDIATE");
  for (const auto& g : games)
    Stmt(db_, "INSERT INTO games VALUES (?1,?2,?3,?4,?5,?6,?7,?8,?9,?10,?11,?12,?13)")
        .text(1, tournament)
        .integer(2, g.index)
        .integer(3, g.round)
        .integer(4, g.home)
        .integer(5, g.away)
        .integer(6, static_cast<int>(g.status))
        .integer(7, g.attempt)
        .text(8, g.request_id)
        .text(9, g.server_id)
        .text(10, g.match_id)
        .num(11, g.home_score)
        .text(12, g.reason)
        .integer(13, g.ticks)
        .step();
  exec("COMMIT");
}

void LeagueStore::update_game(const std::string& tournament, const Game& g) {
  Stmt(
      db_,
      "UPDATE games SET status = ?3, attempt = ?4, request_id = ?5, server_id = ?6, match_id = ?7, "
      "home_score = ?8, reason = ?9, ticks = ?10 WHERE tournament = ?1 AND idx = ?2")
      .text(1, tournament)
      .integer(2, g.index)
      .integer(3, static_cast<int>(g.status))
      .integer(4, g.attempt)
      .text(5, g.request_id)
      .text(6, g.server_id)
      .text(7, g.match_id)
      .num(8, g.home_score)
      .text(9, g.reason)
      .integer(10, g.ticks)
      .step();
}

}  // namespace olympics::selfplay
