#include "tournament.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

namespace olympics::selfplay {
namespace {

TEST(RoundRobin, EveryPairOnceAndNobodyTwiceInARound) {
  for (int n : {2, 3, 4, 5, 8}) {
    auto games = round_robin(n);
    EXPECT_EQ(games.size(), static_cast<size_t>(n * (n - 1) / 2)) << n;
    std::set<std::pair<int, int>> pairs;
    std::map<int, std::set<int>> busy;
    for (const auto& g : games) {
      EXPECT_NE(g.home, g.away);
      EXPECT_TRUE(pairs.insert({std::min(g.home, g.away), std::max(g.home, g.away)}).second);
      EXPECT_TRUE(busy[g.round].insert(g.home).second) << "entrant plays twice in a round";
      EXPECT_TRUE(busy[g.round].insert(g.away).second) << "entrant plays twice in a round";
    }
  }
}

TEST(RoundRobin, DoubleSwapsHomeAndAway) {
  auto games = round_robin(4, true);
  ASSERT_EQ(games.size(), 12u);
  std::set<std::pair<int, int>> ordered;
  for (const auto& g : games) EXPECT_TRUE(ordered.insert({g.home, g.away}).second);
}

TEST(Standings, PointsWinsDrawsLosses) {
  auto table = standings(3, {{0, 1, 1.0}, {1, 2, 0.5}, {2, 0, 1.0}, {0, 1, 0.0}});
  ASSERT_EQ(table.size(), 3u);
  // 0: W L L = 1; 1: L D W = 1.5; 2: D W = 1.5 (one game fewer, same wins: index decides)
  EXPECT_EQ(table[0].entrant, 1);
  EXPECT_EQ(table[0].points, 1.5);
  EXPECT_EQ(table[1].entrant, 2);
  EXPECT_EQ(table[2].entrant, 0);
  EXPECT_EQ(table[2].wins, 1);
  EXPECT_EQ(table[2].losses, 2);
}

}  // namespace
}  // namespace olympics::selfplay

namespace olympics::selfplay {
namespace {

TEST(Swiss, PairsByStandingAvoidsRematchesAndGivesOneByeEach) {
  EXPECT_EQ(swiss_round_count(4), 2);
  EXPECT_EQ(swiss_round_count(5), 3);
  std::vector<GameResult> so_far;
  std::set<std::pair<int, int>> met;
  std::map<int, int> byes;
  for (int round = 0; round < swiss_round_count(5); ++round) {
    auto pairs = swiss_round(5, round, so_far);
    ASSERT_EQ(pairs.size(), 3u);
    std::set<int> seen;
    for (const auto& p : pairs) {
      EXPECT_TRUE(seen.insert(p.home).second);
      if (p.away < 0) {
        ++byes[p.home];
        so_far.push_back({p.home, -1, 1.0});
        continue;
      }
      EXPECT_TRUE(seen.insert(p.away).second);
      EXPECT_TRUE(met.insert({std::min(p.home, p.away), std::max(p.home, p.away)}).second)
          << "rematch in round " << round;
      so_far.push_back({p.home, p.away, p.home < p.away ? 1.0 : 0.0});  // lower index wins
    }
  }
  for (auto [who, n] : byes) EXPECT_EQ(n, 1) << who;
  auto table = standings(5, so_far);
  EXPECT_EQ(table[0].entrant, 0);  // won every game
}

TEST(Knockout, ByesForTopSeedsThenBestMeetsWorst) {
  auto r0 = knockout_round({0, 1, 2, 3, 4, 5}, 0);  // bracket of 8: seeds 0 and 1 rest
  ASSERT_EQ(r0.size(), 4u);
  EXPECT_EQ(r0[0].away, -1);
  EXPECT_EQ(r0[1].away, -1);
  EXPECT_EQ(r0[2].home, 2);
  EXPECT_EQ(r0[2].away, 5);
  EXPECT_EQ(knockout_winner({2, 5, 0.0}), 5);
  EXPECT_EQ(knockout_winner({3, 4, 0.5}), 3);  // draw: better seed
  auto r1 = knockout_round({0, 1, 5, 3}, 1);
  ASSERT_EQ(r1.size(), 2u);
  EXPECT_EQ(r1[0].home, 0);
  EXPECT_EQ(r1[0].away, 3);
}

}  // namespace
}  // namespace olympics::selfplay
