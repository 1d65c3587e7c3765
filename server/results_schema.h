// The results schema, shared by the SQLite and PostgreSQL stores.
#pragma once

#include "results_store.h"

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

// Both stores read rows through these, so the column order is written once. Row is anything with
// text(col), integer(col) and real(col).
inline constexpr const char* kSelectMatches =
    "SELECT match_id, server_id, server_version, sport, mode, seed, realtime, ticks, wall_time_s, "
    "reason, winner_team, scores, info, finished_at_unix, options FROM matches ";
inline constexpr const char* kSelectParticipants =
    "SELECT slot, team, agent, policy, policy_version FROM participants ";

template <typename Row>
StoredMatch match_from_row(const Row& q) {
  StoredMatch m;
  m.match_id = q.text(0), m.server_id = q.text(1), m.server_version = q.text(2);
  m.sport = q.text(3), m.mode = q.text(4), m.seed = q.integer(5), m.realtime = q.integer(6) != 0;
  m.ticks = static_cast<int>(q.integer(7)), m.wall_time_s = q.real(8), m.reason = q.text(9);
  m.winner_team = static_cast<int>(q.integer(10)), m.scores = scores_from_text(q.text(11));
  m.info = q.text(12), m.finished_at_unix = q.integer(13), m.options = q.text(14);
  return m;
}

template <typename Row>
StoredParticipant participant_from_row(const Row& p) {
  return {static_cast<int>(p.integer(0)), static_cast<int>(p.integer(1)), p.text(2), p.text(3),
          p.text(4)};
}

}  // namespace olympics::server
