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
