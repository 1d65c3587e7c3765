#include "league_store.h"

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "sql_database.h"

namespace olympics::selfplay {
namespace {

// One schema for SQLite and PostgreSQL.
constexpr const char* kSchema = R"sql(
CREATE TABLE IF NOT EXISTS tournaments (
  name TEXT PRIMARY KEY, format TEXT NOT NULL, sport TEXT NOT NULL, mode TEXT NOT NULL,
  seed BIGINT NOT NULL, time_limit_s DOUBLE PRECISION NOT NULL, entrants TEXT NOT NULL,
  options TEXT NOT NULL, sport_options TEXT NOT NULL DEFAULT '{}');
CREATE TABLE IF NOT EXISTS games (
  tournament TEXT NOT NULL REFERENCES tournaments(name), idx INTEGER NOT NULL,
  round INTEGER NOT NULL, home INTEGER NOT NULL, away INTEGER NOT NULL, status INTEGER NOT NULL,
  attempt INTEGER NOT NULL, request_id TEXT NOT NULL, server_id TEXT NOT NULL,
  match_id TEXT NOT NULL, home_score DOUBLE PRECISION NOT NULL, reason TEXT NOT NULL,
  ticks INTEGER NOT NULL, seats TEXT NOT NULL DEFAULT '', places TEXT NOT NULL DEFAULT '',
  PRIMARY KEY (tournament, idx));
)sql";
// Added since the first schema, for league databases made before.
constexpr const char* kSportOptionsColumn = "TEXT NOT NULL DEFAULT '{}'";
// A ranked game's seats and places as JSON arrays of integers; '' for a two-team game.
constexpr const char* kRankedColumn = "TEXT NOT NULL DEFAULT ''";

std::string entrants_json(const TournamentSpec& t) {
  nlohmann::json entrants = nlohmann::json::array();
  for (const auto& e : t.entrants)
    entrants.push_back({{"name", e.name}, {"policy", e.policy}, {"seed", e.seed}});
  return entrants.dump();
}

}  // namespace

std::string int_list_text(const std::vector<int>& values) {
  return values.empty() ? "" : nlohmann::json(values).dump();
}

std::vector<int> int_list_from_text(const std::string& text) {
  if (text.empty()) return {};
  return nlohmann::json::parse(text).get<std::vector<int>>();
}

// Every step is committed before it is taken, and must survive even a power loss.
LeagueStore::LeagueStore(const std::string& location)
    : db_(sql::open_sql_database(location, sql::Durability::PowerLoss)) {
  db_->create_schema(kSchema);
  sql::add_column_if_missing(*db_, "tournaments", "sport_options", kSportOptionsColumn);
  sql::add_column_if_missing(*db_, "games", "seats", kRankedColumn);
  sql::add_column_if_missing(*db_, "games", "places", kRankedColumn);
}

LeagueStore::~LeagueStore() = default;

std::optional<TournamentSpec> LeagueStore::find_tournament(const std::string& name) {
  auto rows = db_->query(
      "SELECT format, sport, mode, seed, time_limit_s, entrants, options, sport_options FROM "
      "tournaments WHERE name = $1",
      {name});
  if (rows.empty()) return std::nullopt;
  const auto& r = rows[0];
  TournamentSpec t;
  t.name = name;
  t.format = r[0], t.sport = r[1], t.mode = r[2];
  t.seed = std::stoull(r[3]);
  t.time_limit_s = std::stod(r[4]);
  for (const auto& e : nlohmann::json::parse(r[5]))
    t.entrants.push_back({e.at("name"), e.at("policy"), e.at("seed")});
  t.options = r[6];
  t.sport_options = r[7];
  return t;
}

std::vector<std::string> LeagueStore::tournament_names() {
  std::vector<std::string> out;
  for (const auto& r : db_->query("SELECT name FROM tournaments ORDER BY name"))
    out.push_back(r[0]);
  return out;
}

void LeagueStore::create_tournament(const TournamentSpec& t) {
  db_->query(
      "INSERT INTO tournaments (name, format, sport, mode, seed, time_limit_s, entrants, options, "
      "sport_options) VALUES ($1,$2,$3,$4,$5,$6,$7,$8,$9)",
      {t.name, t.format, t.sport, t.mode, std::to_string(t.seed), sql::exact_text(t.time_limit_s),
       entrants_json(t), t.options.empty() ? "{}" : t.options,
       t.sport_options.empty() ? "{}" : t.sport_options});
}

void LeagueStore::update_entrants(const TournamentSpec& t) {
  db_->query("UPDATE tournaments SET entrants = $2 WHERE name = $1", {t.name, entrants_json(t)});
}

std::vector<Game> LeagueStore::games(const std::string& tournament) {
  std::vector<Game> out;
  for (const auto& r :
       db_->query("SELECT idx, round, home, away, status, attempt, request_id, server_id, "
                  "match_id, home_score, reason, ticks, seats, places FROM games WHERE "
                  "tournament = $1 ORDER BY idx",
                  {tournament})) {
    Game g;
    g.index = std::stoi(r[0]), g.round = std::stoi(r[1]), g.home = std::stoi(r[2]),
    g.away = std::stoi(r[3]);
    g.status = static_cast<GameStatus>(std::stoi(r[4]));
    g.attempt = std::stoi(r[5]);
    g.request_id = r[6], g.server_id = r[7], g.match_id = r[8];
    g.home_score = std::stod(r[9]), g.reason = r[10], g.ticks = std::stoi(r[11]);
    g.seats = int_list_from_text(r[12]), g.places = int_list_from_text(r[13]);
    out.push_back(g);
  }
  return out;
}

void LeagueStore::add_games(const std::string& tournament, const std::vector<Game>& games) {
  db_->transaction([&] {
    for (const auto& g : games)
      db_->query(
          "INSERT INTO games (tournament, idx, round, home, away, status, attempt, request_id, "
          "server_id, match_id, home_score, reason, ticks, seats, places) "
          "VALUES ($1,$2,$3,$4,$5,$6,$7,$8,$9,$10,$11,$12,$13,$14,$15)",
          {tournament, std::to_string(g.index), std::to_string(g.round), std::to_string(g.home),
           std::to_string(g.away), std::to_string(static_cast<int>(g.status)),
           std::to_string(g.attempt), g.request_id, g.server_id, g.match_id,
           sql::exact_text(g.home_score), g.reason, std::to_string(g.ticks), int_list_text(g.seats),
           int_list_text(g.places)});
  });
}

void LeagueStore::update_game(const std::string& tournament, const Game& g) {
  db_->query(
      "UPDATE games SET status = $3, attempt = $4, request_id = $5, server_id = $6, match_id = $7, "
      "home_score = $8, reason = $9, ticks = $10, places = $11 WHERE tournament = $1 AND idx = $2",
      {tournament, std::to_string(g.index), std::to_string(static_cast<int>(g.status)),
       std::to_string(g.attempt), g.request_id, g.server_id, g.match_id,
       sql::exact_text(g.home_score), g.reason, std::to_string(g.ticks), int_list_text(g.places)});
}

}  // namespace olympics::selfplay
