// The fleet carries ranked fixtures of N entrants (athletics competition_N): a heat of four
// queued in PostgreSQL (OLYMPICS_TEST_POSTGRES_URL; skipped without it, as the other PostgreSQL
// tests) is leased by a cell, played on the cell's own server by four agent processes, and
// stored once with its four places, in the league's games row and in fleet_results, and rated.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <set>

#include "leaderboard.h"
#include "league_store.h"
#include "results_store.h"
#include "sql_database.h"
#include "test_programs.h"

namespace olympics::testing {
namespace {

TEST(FleetRanked, ACellPlaysAQueuedHeatOfFourAndStoresItsPlacesOnce) {
  const char* pg = std::getenv("OLYMPICS_TEST_POSTGRES_URL");
  if (!pg) GTEST_SKIP() << "set OLYMPICS_TEST_POSTGRES_URL (CI does)";
  const std::string url = pg, dir = temp_dir();
  const std::string name =
      "heat" + std::to_string(std::chrono::system_clock::now().time_since_epoch().count());
  Process queue({program("olympics-league"), "run", "--fleet", "--db", url, "--name", name,
                 "--sport", "long_jump", "--mode", "competition_4", "--options",
                 R"({"rules": "official", "attempts": 1, "attempt_s": 2})", "--entrants",
                 "zero,random:1,zero,random:2", "--seed", "3"},
                dir + "/queue.log");
  ASSERT_EQ(queue.wait(60), 0) << queue.output();
  Process cell(
      {program("olympics-league"), "cell", "--db", url, "--name", name, "--cell", "lane-cell",
       "--spawn-server", "--lcm-url", unique_lcm_url(), "--log-dir", dir, "--server-wait-s", "30"},
      dir + "/cell.log");
  ASSERT_EQ(cell.wait(300), 0) << cell.output();

  selfplay::LeagueStore store(url);
  const auto spec = store.find_tournament(name);
  ASSERT_TRUE(spec);
  const auto games = store.games(name);
  ASSERT_EQ(games.size(), 1u) << "four entrants: one heat of four";
  const auto& g = games[0];
  EXPECT_EQ(g.status, selfplay::GameStatus::Done);
  ASSERT_EQ(g.seats.size(), 4u);
  EXPECT_EQ(std::set<int>(g.seats.begin(), g.seats.end()).size(), 4u);
  ASSERT_EQ(g.places.size(), 4u);
  // The cell's server recorded the match with the same places and each seat's entrant.
  auto record = server::open_results_store(dir + "/lane_cell-results.db")->find(g.match_id);
  ASSERT_TRUE(record) << g.match_id;
  EXPECT_EQ(nlohmann::json::parse(record->info).at("places").get<std::vector<int>>(), g.places);
  ASSERT_EQ(record->participants.size(), 4u);
  for (size_t slot = 0; slot < 4; ++slot)
    EXPECT_EQ(record->participants[slot].agent, spec->entrants[g.seats[slot]].name);
  // fleet_results holds the places too (the queue's own record of the result).
  auto db = sql::open_sql_database(url);
  const auto rows =
      db->query("SELECT places FROM fleet_results WHERE tournament = $1 AND idx = 0", {name});
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(selfplay::int_list_from_text(rows[0][0]), g.places);
  // Rated: every athlete's sigma shrank.
  const auto board = selfplay::compute_leaderboard(*spec, games);
  for (const auto& row : board.rows) EXPECT_LT(row.skill.sigma, 25.0 / 3.0) << row.name;
}

}  // namespace
}  // namespace olympics::testing
