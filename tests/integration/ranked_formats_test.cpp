// The league's knockout and swiss of heats (competition_4, eight entrants) over a real server
// and agent processes: each round is drawn from the places the server stored for the round
// before it. Knockout: two heats, then the final of their top twos (a tie at the cut goes to the
// better seed); swiss: three rounds of two heats, the later ones drawn by standing.
#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>

#include "heat_rounds.h"
#include "league_run_args.h"
#include "league_store.h"
#include "server_fixture.h"

namespace olympics::testing {
namespace {

std::vector<selfplay::Game> play_heats(const std::string& format, const std::string& dir) {
  ServerFixture server;
  const std::string db = dir + "/league.db";
  const LeagueRun heats{db,
                        "rounds",
                        "long_jump",
                        "competition_4",
                        R"({"rules": "official", "attempts": 1, "attempt_s": 2})",
                        format,
                        "zero,random:1,zero,random:2,zero,random:3,zero,random:4",
                        5};
  Process run(league_run_args(heats, server.url(), dir), dir + "/league.log");
  EXPECT_EQ(run.wait(300), 0) << run.output();
  selfplay::LeagueStore store(db);
  auto games = store.games("rounds");
  for (const auto& g : games) {
    EXPECT_EQ(g.status, selfplay::GameStatus::Done) << g.index;
    EXPECT_EQ(g.seats.size(), 4u) << g.index;
    EXPECT_EQ(g.places.size(), 4u) << g.index;
    auto record = server.store()->find(g.match_id);
    EXPECT_TRUE(record) << g.match_id;
    if (record) {
      EXPECT_EQ(nlohmann::json::parse(record->info).at("places").get<std::vector<int>>(), g.places);
    }
  }
  return games;
}

std::vector<selfplay::HeatResult> before_round(const std::vector<selfplay::Game>& games,
                                               int round) {
  std::vector<selfplay::HeatResult> out;
  for (const auto& g : games)
    if (g.round < round) out.push_back({g.round, g.seats, g.places});
  return out;
}

std::vector<std::vector<int>> seats_of_round(const std::vector<selfplay::Game>& games, int round) {
  std::vector<std::vector<int>> out;
  for (const auto& g : games)
    if (g.round == round) out.push_back(g.seats);
  return out;
}

TEST(RankedFormats, AKnockoutOfEightInHeatsOfFourEndsWithTheFinalOfTheHeatsTopTwos) {
  const auto games = play_heats("knockout", temp_dir());
  ASSERT_EQ(games.size(), 3u) << "two heats and the final";
  EXPECT_EQ(games[0].round, 0);
  EXPECT_EQ(games[1].round, 0);
  EXPECT_EQ(games[2].round, 1);
  // The final: from each heat the two best places, a tie to the better seed (lower index).
  std::set<int> expected;
  for (int h = 0; h < 2; ++h) {
    const auto& g = games[h];
    std::vector<int> order = {0, 1, 2, 3};
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      return g.places[a] != g.places[b] ? g.places[a] < g.places[b] : g.seats[a] < g.seats[b];
    });
    expected.insert(g.seats[order[0]]);
    expected.insert(g.seats[order[1]]);
  }
  EXPECT_EQ(std::set<int>(games[2].seats.begin(), games[2].seats.end()), expected);
}

TEST(RankedFormats, ASwissOfEightInHeatsOfFourDrawsEachRoundFromTheStoredPlaces) {
  const auto games = play_heats("swiss", temp_dir());
  ASSERT_EQ(games.size(), 6u) << "three rounds of two heats";
  for (int round = 0; round < 3; ++round) {
    std::vector<std::vector<int>> drawn;
    for (const auto& p : selfplay::swiss_heats_round(8, 4, before_round(games, round)))
      drawn.push_back(p.seats);
    EXPECT_EQ(seats_of_round(games, round), drawn) << "round " << round;
  }
}

}  // namespace
}  // namespace olympics::testing
