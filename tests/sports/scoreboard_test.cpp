// Tennis and table-tennis scoring against the rules, point by point.
#include "racket/scoreboard.h"

#include <gtest/gtest.h>

namespace olympics::sports::racket {
namespace {

void win_points(Scoreboard& s, int team, int n) {
  for (int i = 0; i < n; ++i) s.point_won(team);
}

TEST(TennisScore, GameCallsDeuceAdvantageAndServerChange) {
  TennisScore s({}, /*first_server=*/0);
  EXPECT_EQ(s.text(), "0-0 0-0");
  s.point_won(0);
  EXPECT_EQ(s.text(), "0-0 15-0");
  win_points(s, 1, 3);
  EXPECT_EQ(s.text(), "0-0 15-40");
  win_points(s, 0, 2);
  EXPECT_EQ(s.text(), "0-0 deuce");
  s.point_won(1);
  EXPECT_EQ(s.text(), "0-0 advantage 1");
  s.point_won(0);
  EXPECT_EQ(s.text(), "0-0 deuce");
  EXPECT_EQ(s.server(), 0);
  win_points(s, 0, 2);
  EXPECT_EQ(s.games()[0], 1);
  EXPECT_EQ(s.server(), 1);  // the other side serves the next game
}

TEST(TennisScore, SetGoesToTiebreakAtSixAllAndIsWonThere) {
  TennisScore s({}, 0);
  for (int g = 0; g < 6; ++g) win_points(s, 0, 4), win_points(s, 1, 4);
  EXPECT_TRUE(s.in_tiebreak());
  EXPECT_EQ(s.text(), "6-6 tie-break 0-0");
  // Tie-break service: first point by the game's server, then two each.
  const int server = s.server();
  std::vector<int> servers;
  for (int p = 0; p < 6; ++p) servers.push_back(s.server()), s.point_won(p % 2);
  EXPECT_EQ(servers,
            (std::vector<int>{server, 1 - server, 1 - server, server, server, 1 - server}));
  EXPECT_EQ(s.text(), "6-6 tie-break 3-3");
  win_points(s, 1, 3);  // 3-6, 7th point wins only with a 2-point lead: 3-7
  EXPECT_FALSE(s.over());
  s.point_won(1);
  EXPECT_TRUE(s.over());
  EXPECT_EQ(s.winner(), 1);
  EXPECT_EQ(s.text(), "6-7");
  EXPECT_EQ(s.scores()[1], 1.0f);
}

TEST(TennisScore, SetNeedsTwoGamesLeadBeforeSixAll) {
  TennisFormat f;
  f.sets_to_win = 2;
  TennisScore s(f, 1);
  for (int g = 0; g < 5; ++g) win_points(s, 0, 4), win_points(s, 1, 4);
  win_points(s, 0, 4);  // 6-5: not yet
  EXPECT_EQ(s.sets()[0], 0);
  win_points(s, 0, 4);  // 7-5
  EXPECT_EQ(s.sets()[0], 1);
  EXPECT_FALSE(s.over());
  EXPECT_EQ(s.leader(), 0);
  for (int g = 0; g < 6; ++g) win_points(s, 0, 4);
  EXPECT_TRUE(s.over());
  EXPECT_EQ(s.text(), "7-5 6-0");
}

TEST(TennisScore, TiebreakOnlyFormatIsOneGameToSevenByTwo) {
  TennisFormat f;
  f.tiebreak_only = true;
  TennisScore s(f, 0);
  win_points(s, 0, 6);
  win_points(s, 1, 6);
  s.point_won(0);
  EXPECT_FALSE(s.over());  // 7-6
  s.point_won(0);
  EXPECT_TRUE(s.over());
  EXPECT_EQ(s.winner(), 0);
  EXPECT_EQ(s.points_played(), 14);
}

TEST(TableTennisScore, ElevenWinByTwoServiceEveryTwoThenEveryPoint) {
  TableTennisScore s({}, 1);
  std::vector<int> servers;
  for (int p = 0; p < 4; ++p) servers.push_back(s.server()), s.point_won(p % 2);
  EXPECT_EQ(servers, (std::vector<int>{1, 1, 0, 0}));
  while (s.points()[0] < 10) s.point_won(0);
  while (s.points()[1] < 10) s.point_won(1);
  EXPECT_EQ(s.text(), "10-10");
  const int a = s.server();
  s.point_won(0);
  EXPECT_EQ(s.server(), 1 - a);  // from 10-10 service changes every point
  EXPECT_FALSE(s.over());
  s.point_won(0);
  EXPECT_TRUE(s.over());
  EXPECT_EQ(s.text(), "12-10");
}

TEST(TableTennisScore, BestOfThreeAlternatesFirstServer) {
  TableTennisScore s({2, 11}, 0);
  win_points(s, 1, 11);
  EXPECT_EQ(s.server(), 1);  // the other side serves first in game 2
  EXPECT_FALSE(s.over());
  win_points(s, 1, 11);
  EXPECT_TRUE(s.over());
  EXPECT_EQ(s.winner(), 1);
  EXPECT_EQ(s.text(), "0-11 0-11");
}

}  // namespace
}  // namespace olympics::sports::racket
