// The league's ranked fixtures of N entrants (athletics competition_N): heat schedules, the
// scheduler's fixtures, the ranking read from a match's info["places"], the table and ratings
// they give (for N = 2 exactly a two-team game's), and their storage.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "heats.h"
#include "leaderboard.h"
#include "league_store.h"
#include "scheduler.h"
#include "sql_database.h"
#include "tournament_runner.h"

namespace olympics::selfplay {
namespace {

// How often each pair met, and each entrant's appearances, over a schedule of heats.
struct Coverage {
  std::map<std::pair<int, int>, int> met;
  std::map<int, int> appearances;
};

Coverage coverage(const std::vector<Pairing>& schedule) {
  Coverage c;
  for (const auto& h : schedule) {
    for (size_t i = 0; i < h.seats.size(); ++i) {
      ++c.appearances[h.seats[i]];
      for (size_t j = i + 1; j < h.seats.size(); ++j)
        ++c.met[{std::min(h.seats[i], h.seats[j]), std::max(h.seats[i], h.seats[j])}];
    }
  }
  return c;
}

TEST(Heats, EveryPairMeetsAndAppearancesStayBalanced) {
  for (int seats = 2; seats <= 8; ++seats)
    for (int entrants = seats; entrants <= 12; ++entrants)
      for (int meetings : {1, 2})
        for (std::uint64_t seed : {1u, 7u}) {
          const auto schedule = heats(entrants, seats, seed, meetings);
          const auto c = coverage(schedule);
          SCOPED_TRACE(testing::Message() << entrants << " entrants, heats of " << seats
                                          << ", meetings " << meetings << ", seed " << seed);
          std::map<int, std::set<int>> busy;  // nobody twice in a round
          for (const auto& h : schedule) {
            ASSERT_EQ(h.seats.size(), static_cast<size_t>(seats));
            EXPECT_EQ(h.home, h.seats[0]);
            EXPECT_EQ(h.away, h.seats[1]);
            for (int e : h.seats) {
              ASSERT_GE(e, 0);
              ASSERT_LT(e, entrants);
              EXPECT_TRUE(busy[h.round].insert(e).second);
            }
          }
          for (int a = 0; a < entrants; ++a)
            for (int b = a + 1; b < entrants; ++b) {
              auto it = c.met.find({a, b});
              EXPECT_GE(it == c.met.end() ? 0 : it->second, meetings) << a << "-" << b;
            }
          int lo = 1 << 30, hi = 0;
          for (int e = 0; e < entrants; ++e)
            lo = std::min(lo, c.appearances.count(e) ? c.appearances.at(e) : 0),
            hi = std::max(hi, c.appearances.count(e) ? c.appearances.at(e) : 0);
          EXPECT_LE(hi - lo, 1) << "appearances differ by more than one";
        }
}

TEST(Heats, AFieldOfNIsOneHeatAndSchedulesAreAFunctionOfTheSeed) {
  const auto one = heats(8, 8, 3);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(std::set<int>(one[0].seats.begin(), one[0].seats.end()).size(), 8u);
  // Eight entrants in heats of four: 28 pairs, 12 per round of two heats: at least three rounds.
  const auto a = heats(8, 4, 5), b = heats(8, 4, 5), other = heats(8, 4, 6);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].seats, b[i].seats);
  EXPECT_GE(a.size(), 6u);
  EXPECT_LE(a.size(), 10u) << "the greedy draw should cover 28 pairs in a few rounds";
  bool differs = a.size() != other.size();
  for (size_t i = 0; !differs && i < a.size(); ++i) differs = a[i].seats != other[i].seats;
  EXPECT_TRUE(differs) << "another seed, another draw";
}

TEST(RankedTournament, ModesAndRefusals) {
  EXPECT_EQ(ranked_seats("competition_8"), 8);
  EXPECT_EQ(ranked_seats("competition_2"), 2);
  EXPECT_EQ(ranked_seats("1v1"), 0);
  EXPECT_EQ(ranked_seats("solo"), 0);
  EXPECT_NO_THROW(check_ranked_tournament("competition_8", "round-robin", 8));
  EXPECT_NO_THROW(check_ranked_tournament("competition_2", "knockout", 5));
  EXPECT_NO_THROW(check_ranked_tournament("2v2", "swiss", 3));
  try {
    check_ranked_tournament("competition_8", "round-robin", 5);
    ADD_FAILURE() << "five entrants cannot fill heats of eight";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("add entrants, or choose competition_5"),
              std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(check_ranked_tournament("competition_4", "swiss", 8));
  EXPECT_NO_THROW(check_ranked_tournament("competition_4", "knockout", 8));
  try {
    check_ranked_tournament("competition_4", "selfplay", 8);
    ADD_FAILURE() << "self-play pairs two";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--format round-robin"), std::string::npos) << e.what();
  }
}

TournamentSpec spec_of(int entrants, const std::string& mode, const std::string& format) {
  TournamentSpec spec;
  spec.name = "t", spec.format = format, spec.mode = mode, spec.sport = "long_jump";
  spec.seed = 4;
  for (int i = 0; i < entrants; ++i) {
    std::string name = "e";  // (not "e" + to_string: GCC 12's -Wrestrict false positive)
    name += std::to_string(i);
    spec.entrants.push_back({name, "zero", 1});
  }
  return spec;
}

TEST(RankedTournament, TheSchedulerSeatsHeatsOnceThenFinishes) {
  auto spec = spec_of(6, "competition_4", "round-robin");
  auto scheduler = make_tournament_scheduler();
  std::vector<Pairing> out;
  ASSERT_EQ(scheduler->schedule(spec, {}, out), Scheduler::Verdict::Added);
  EXPECT_EQ(out.size(), heats(6, 4, 4).size());
  std::vector<Game> games;
  for (const auto& p : out) {
    ASSERT_EQ(p.seats.size(), 4u);
    Game g;
    g.index = static_cast<int>(games.size()), g.home = p.home, g.away = p.away, g.seats = p.seats;
    games.push_back(g);
  }
  std::vector<Pairing> more;
  EXPECT_EQ(scheduler->schedule(spec, games, more), Scheduler::Verdict::Wait);
  for (auto& g : games) g.status = GameStatus::Done, g.places = {1, 2, 3, 4};
  EXPECT_EQ(scheduler->schedule(spec, games, more), Scheduler::Verdict::Finished);
  EXPECT_TRUE(more.empty());
  // Nor can a format that pairs two.
  auto pairs_two = spec_of(6, "competition_4", "selfplay");
  EXPECT_THROW(scheduler->schedule(pairs_two, {}, out), std::invalid_argument);
}

TEST(RankedTournament, CompetitionsOfTwoPairAsTwoTeamsDoEachARankedFixture) {
  auto spec = spec_of(5, "competition_2", "swiss");
  std::vector<Pairing> out;
  ASSERT_EQ(make_tournament_scheduler()->schedule(spec, {}, out), Scheduler::Verdict::Added);
  ASSERT_EQ(out.size(), 3u);  // two games and a bye
  for (const auto& p : out) {
    if (p.away < 0)
      EXPECT_TRUE(p.seats.empty());
    else
      EXPECT_EQ(p.seats, (std::vector<int>{p.home, p.away}));
  }
}

TEST(RankedResult, PlacesComeFromTheMatchInfo) {
  EXPECT_EQ(ranked_places(R"({"places": [2, 1, 3, 3], "events": []})", 4, 1),
            (std::vector<int>{2, 1, 3, 3}));
  // Everyone failed: all first, a draw among all.
  EXPECT_EQ(ranked_places(R"({"places": [1, 1, 1]})", 3, -1), (std::vector<int>{1, 1, 1}));
  // No usable ranking (none, the wrong count, a place below 1, not JSON): the winner first, the
  // rest tied; no winner: all tied.
  EXPECT_EQ(ranked_places(R"({"score": 3})", 3, 2), (std::vector<int>{2, 2, 1}));
  EXPECT_EQ(ranked_places(R"({"places": [1, 2]})", 3, 0), (std::vector<int>{1, 2, 2}));
  EXPECT_EQ(ranked_places(R"({"places": [1, 0, 2]})", 3, -1), (std::vector<int>{1, 1, 1}));
  EXPECT_EQ(ranked_places("not json", 2, 1), (std::vector<int>{2, 1}));
}

Game done_game(int index, int home, int away, double home_score) {
  Game g;
  g.index = index, g.home = home, g.away = away, g.home_score = home_score;
  g.status = GameStatus::Done;
  return g;
}

Game ranked_game(int index, std::vector<int> seats, std::vector<int> places) {
  Game g = done_game(index, seats[0], seats[1], pair_score(places[0], places[1]));
  g.seats = std::move(seats), g.places = std::move(places);
  return g;
}

// A ranked fixture of two is rated, tabled and recorded exactly as the two-team game with the
// same result: the same Weng-Lin and Elo numbers to the bit.
TEST(RankedLeaderboard, TwoSeatsGiveTheTwoTeamNumbers) {
  const auto spec = spec_of(3, "competition_2", "round-robin");
  const std::vector<Game> two_team = {done_game(0, 0, 1, 1.0), done_game(1, 2, 0, 0.5),
                                      done_game(2, 1, 2, 0.0), done_game(3, 0, 1, 0.0)};
  const std::vector<Game> ranked = {ranked_game(0, {0, 1}, {1, 2}), ranked_game(1, {2, 0}, {1, 1}),
                                    ranked_game(2, {1, 2}, {2, 1}), ranked_game(3, {0, 1}, {2, 1})};
  const auto a = compute_leaderboard(spec, two_team), b = compute_leaderboard(spec, ranked);
  ASSERT_EQ(a.rows.size(), b.rows.size());
  for (size_t i = 0; i < a.rows.size(); ++i) {
    EXPECT_EQ(a.rows[i].name, b.rows[i].name);
    EXPECT_EQ(a.rows[i].skill.mu, b.rows[i].skill.mu);
    EXPECT_EQ(a.rows[i].skill.sigma, b.rows[i].skill.sigma);
    EXPECT_EQ(a.rows[i].elo, b.rows[i].elo);
    EXPECT_EQ(a.rows[i].standing.points, b.rows[i].standing.points);
    EXPECT_EQ(a.rows[i].standing.wins, b.rows[i].standing.wins);
    EXPECT_EQ(a.rows[i].standing.draws, b.rows[i].standing.draws);
  }
  EXPECT_EQ(a.mu_history, b.mu_history);
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y) {
      if (x == y) continue;
      EXPECT_EQ(a.payoff.win_rate(x, y), b.payoff.win_rate(x, y));
    }
  EXPECT_NE(a.rows[0].skill.mu, 25.0) << "the games should move the ratings";
}

// A heat of three (entrants 2, 0, 1 in lanes 0-2, placed 1, 3, 2): one three-team Weng-Lin
// update (the hand-computed one of ratings_test), pairwise points and Elo.
TEST(RankedLeaderboard, AHeatOfThreeIsOneMultiTeamUpdate) {
  const auto spec = spec_of(3, "competition_3", "round-robin");
  const auto board = compute_leaderboard(spec, {ranked_game(0, {2, 0, 1}, {1, 3, 2})});
  ASSERT_EQ(board.rows.size(), 3u);
  const double step = 150.0 / (9.0 * std::sqrt(10.0));
  EXPECT_EQ(board.rows[0].name, "e2");
  EXPECT_NEAR(board.rows[0].skill.mu, 25.0 + step, 1e-12);
  EXPECT_EQ(board.rows[0].standing.wins, 2);
  EXPECT_EQ(board.rows[0].standing.points, 2.0);
  EXPECT_DOUBLE_EQ(board.rows[0].elo, 1516);
  EXPECT_EQ(board.rows[1].name, "e1");
  EXPECT_NEAR(board.rows[1].skill.mu, 25.0, 1e-12);
  EXPECT_EQ(board.rows[1].standing.played, 2);
  EXPECT_EQ(board.rows[2].name, "e0");
  EXPECT_NEAR(board.rows[2].skill.mu, 25.0 - step, 1e-12);
  EXPECT_EQ(board.rows[2].standing.losses, 2);
  EXPECT_EQ(board.payoff.win_rate(2, 0), 1.0);
  EXPECT_EQ(board.payoff.win_rate(0, 1), 0.0);
  ASSERT_EQ(board.mu_history[2].size(), 2u);  // before, and after the one game
}

TEST(RankedStore, SeatsAndPlacesAreStoredAndOldDatabasesGainTheColumns) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("ranked-store-" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string db = (dir / "league.db").string();
  {  // a league database of the schema before ranked games
    auto old = sql::open_sql_database(db);
    old->create_schema(R"sql(
CREATE TABLE tournaments (
  name TEXT PRIMARY KEY, format TEXT NOT NULL, sport TEXT NOT NULL, mode TEXT NOT NULL,
  seed BIGINT NOT NULL, time_limit_s DOUBLE PRECISION NOT NULL, entrants TEXT NOT NULL,
  options TEXT NOT NULL, sport_options TEXT NOT NULL DEFAULT '{}');
CREATE TABLE games (
  tournament TEXT NOT NULL REFERENCES tournaments(name), idx INTEGER NOT NULL,
  round INTEGER NOT NULL, home INTEGER NOT NULL, away INTEGER NOT NULL, status INTEGER NOT NULL,
  attempt INTEGER NOT NULL, request_id TEXT NOT NULL, server_id TEXT NOT NULL,
  match_id TEXT NOT NULL, home_score DOUBLE PRECISION NOT NULL, reason TEXT NOT NULL,
  ticks INTEGER NOT NULL, PRIMARY KEY (tournament, idx));
INSERT INTO tournaments VALUES ('old', 'round-robin', 'sandbox', '1v1', 1, 0, '[]', '{}', '{}');
INSERT INTO games VALUES ('old', 0, 0, 0, 1, 2, 0, 'r', 's', 'm', 1, 'time_limit', 5);
)sql");
  }
  LeagueStore store(db);
  const auto old = store.games("old");
  ASSERT_EQ(old.size(), 1u);
  EXPECT_FALSE(old[0].ranked());
  EXPECT_TRUE(old[0].places.empty());

  auto spec = spec_of(8, "competition_8", "round-robin");
  store.create_tournament(spec);
  Game g;
  g.seats = {3, 1, 4, 0, 5, 2, 6, 7}, g.home = 3, g.away = 1;
  store.add_games("t", {g});
  auto stored = store.games("t");
  ASSERT_EQ(stored.size(), 1u);
  EXPECT_EQ(stored[0].seats, g.seats);
  EXPECT_TRUE(stored[0].places.empty());
  g.status = GameStatus::Done, g.places = {2, 1, 3, 3, 5, 6, 7, 8};
  store.update_game("t", g);
  stored = store.games("t");
  EXPECT_EQ(stored[0].places, g.places);
  EXPECT_EQ(stored[0].entrants(), g.seats);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace olympics::selfplay
