// The results schema, shared by the SQLite and PostgreSQL stores: SQL text only (the store reads
// its rows into StoredMatch, results_store.cpp).
#pragma once

namespace olympics::server {

inline constexpr const char* kResultsSchema = R"sql(
CREATE TABLE IF NOT EXISTS matches (
  match_id         TEXT PRIMARY KEY,
  server_id        TEXT NOT NULL,
  server_version   TEXT NOT NULL,
  sport            TEXT NOT NULL,
  mode             TEXT NOT NULL,
  seed             BIGINT NOT NULL,
  realtime         INTEGER NOT NULL,
  ticks            INTEGER NOT NULL,
  wall_time_s      DOUBLE PRECISION NOT NULL,
  reason           TEXT NOT NULL,
  winner_team      INTEGER NOT NULL,
  scores           TEXT NOT NULL,
  info             TEXT NOT NULL,
  finished_at_unix BIGINT NOT NULL,
  options          TEXT NOT NULL DEFAULT '{}'
);
CREATE TABLE IF NOT EXISTS participants (
  match_id       TEXT NOT NULL REFERENCES matches(match_id),
  slot           INTEGER NOT NULL,
  team           INTEGER NOT NULL,
  agent          TEXT NOT NULL,
  policy         TEXT NOT NULL,
  policy_version TEXT NOT NULL,
  PRIMARY KEY (match_id, slot)
);
CREATE INDEX IF NOT EXISTS matches_finished ON matches(finished_at_unix);
CREATE TABLE IF NOT EXISTS matches_in_progress (
  match_id        TEXT PRIMARY KEY,
  server_id       TEXT NOT NULL,
  sport           TEXT NOT NULL,
  mode            TEXT NOT NULL,
  seed            BIGINT NOT NULL,
  realtime        INTEGER NOT NULL,
  options         TEXT NOT NULL,
  participants    TEXT NOT NULL,
  created_at_unix BIGINT NOT NULL
);
)sql";

// Columns added since the first schema, for stores made before them: (column, definition).
inline constexpr const char* kResultsAddedColumns[][2] = {
    {"options", "TEXT NOT NULL DEFAULT '{}'"},  // protocol 3: the sport's settings in force
};

// Both stores read rows in this column order (results_store.cpp: match_from_row(),
// participant_from_row()), so it is written once.
inline constexpr const char* kSelectMatches =
    "SELECT match_id, server_id, server_version, sport, mode, seed, realtime, ticks, wall_time_s, "
    "reason, winner_team, scores, info, finished_at_unix, options FROM matches ";
inline constexpr const char* kSelectParticipants =
    "SELECT slot, team, agent, policy, policy_version FROM participants ";

}  // namespace olympics::server
