// The results schema, shared by the SQLite and PostgreSQL stores.
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
  finished_at_unix BIGINT NOT NULL
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
)sql";

}  // namespace olympics::server
