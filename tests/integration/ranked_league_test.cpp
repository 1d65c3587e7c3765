// The league plays and rates a ranked athletics competition over a real server: eight entrants
// seated in one competition_8 heat, each played by an olympics-agent process the league starts;
// the game is stored with the eight places of the server's record (info["places"]) and the
// table rates them with one eight-team Weng-Lin update. The sport is the test's parameter: the
// field events and the 8-athlete hurdles race of issue 31.
// And a tournament of heats killed with SIGKILL resumes to the table of an uninterrupted one.
#include <chrono>
#include <csignal>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>

#include "leaderboard.h"
#include "league_run_args.h"
#include "league_store.h"
#include "ratings.h"
#include "server_fixture.h"

namespace olympics::testing {
namespace {

// How the server's scores (the stored record's) rank the athletes: the best marks (0 = none
// valid), the race times (0 = did not finish) or the strokes to hole out.
enum class Ranking { LongestMark, FastestTime, FewestStrokes };

struct RankedSport {
  std::string sport;
  std::string options;  // short: one attempt each (the race: up to ~110 s of match time)
  std::string entrants;
  int seed;         // the league's --seed (the heat's match seed and seats follow from it)
  Ranking ranking;  // the high jump's LongestMark (best height) holds for one height, one try
  bool distinct;    // the heat's places must not be all equal (entrants that score)
};

// gtest names a failing instance by this, not by the struct's bytes.
void PrintTo(const RankedSport& s, std::ostream* os) {
  *os << s.sport << " " << s.options << ", entrants " << s.entrants << ", seed " << s.seed;
}

// Whether athlete a's score beats b's under the sport's ranking.
bool beats(Ranking ranking, double a, double b) {
  switch (ranking) {
    case Ranking::LongestMark:
      return a > b;
    case Ranking::FastestTime:
      return a > 0 && (b == 0 || a < b);
    case Ranking::FewestStrokes:
      return a < b;
  }
  return false;
}

class RankedLeague : public ::testing::TestWithParam<RankedSport> {};

TEST_P(RankedLeague, AnEightAthleteCompetitionIsStoredWithEightRankedPlacesAndRated) {
  const RankedSport& param = GetParam();
  ServerFixture server;
  const std::string dir = temp_dir(), db = dir + "/league.db";
  const LeagueRun final_heat{db,
                             "final",
                             param.sport,
                             "competition_8",
                             param.options,
                             "round-robin",
                             param.entrants,
                             param.seed};
  Process run(league_run_args(final_heat, server.url(), dir), dir + "/league.log");
  ASSERT_EQ(run.wait(300), 0) << run.output();

  selfplay::LeagueStore store(db);
  const auto spec = store.find_tournament("final");
  ASSERT_TRUE(spec);
  ASSERT_EQ(spec->entrants.size(), 8u);
  const auto games = store.games("final");
  ASSERT_EQ(games.size(), 1u) << "eight entrants fill one heat of eight";
  const auto& g = games[0];
  EXPECT_EQ(g.status, selfplay::GameStatus::Done);
  ASSERT_EQ(g.seats.size(), 8u);
  EXPECT_EQ(std::set<int>(g.seats.begin(), g.seats.end()).size(), 8u) << "each entrant one seat";
  ASSERT_EQ(g.places.size(), 8u);

  // The server's record: the entrant of each seat in that slot, the same eight places.
  auto record = server.store()->find(g.match_id);
  ASSERT_TRUE(record) << g.match_id;
  EXPECT_EQ(record->sport, param.sport);
  EXPECT_EQ(record->mode, "competition_8");
  ASSERT_EQ(record->participants.size(), 8u);
  for (size_t slot = 0; slot < 8; ++slot)
    EXPECT_EQ(record->participants[slot].agent, spec->entrants[g.seats[slot]].name) << slot;
  const auto info = nlohmann::json::parse(record->info);
  EXPECT_EQ(info.at("places").get<std::vector<int>>(), g.places) << record->info;
  for (int p : g.places) {
    EXPECT_GE(p, 1);
    EXPECT_LE(p, 8);
  }
  // The places agree with the marks, times or strokes the server stored: each athlete is placed
  // behind everyone who beat it and ahead of everyone it beat. Equal scores share a place unless
  // the rules break the tie (the high jump's countback and jump-off: a jump-off's heights are not
  // best heights), so an athlete level with k others is placed within those k places.
  ASSERT_EQ(record->scores.size(), 8u);
  for (size_t a = 0; a < 8; ++a) {
    int beaten_by = 0, level_with = 0;
    for (size_t b = 0; b < 8; ++b) {
      if (b == a) continue;
      if (beats(param.ranking, record->scores[b], record->scores[a]))
        ++beaten_by;
      else if (!beats(param.ranking, record->scores[a], record->scores[b]))
        ++level_with;
    }
    EXPECT_GE(g.places[a], 1 + beaten_by) << "slot " << a << ": " << record->info;
    EXPECT_LE(g.places[a], 1 + beaten_by + level_with) << "slot " << a << ": " << record->info;
  }
  if (param.distinct) {
    EXPECT_GT(std::set<int>(g.places.begin(), g.places.end()).size(), 1u)
        << "an all-way tie: " << record->info;
  }

  // Rated by the league: one eight-team update over the stored places.
  std::vector<std::vector<selfplay::SkillRating>> field(8, {selfplay::SkillRating{}});
  const auto expected = selfplay::rate_match(field, g.places);
  const auto board = selfplay::compute_leaderboard(*spec, games);
  ASSERT_EQ(board.rows.size(), 8u);
  for (const auto& row : board.rows) {
    const int seat = static_cast<int>(
        std::find(g.seats.begin(), g.seats.end(), row.standing.entrant) - g.seats.begin());
    EXPECT_EQ(row.skill.mu, expected[seat][0].mu) << row.name;
    EXPECT_EQ(row.skill.sigma, expected[seat][0].sigma) << row.name;
    EXPECT_LT(row.skill.sigma, 25.0 / 3.0) << row.name << " was not rated";
    EXPECT_EQ(row.standing.played, 7) << "a heat of eight: seven pairwise results each";
  }
  // The ratings after the heat order the entrants as their places do: from equal priors, an
  // athlete placed ahead (a finisher ahead of a non-finisher, a longer mark) rates higher, and
  // equal places rate equal.
  std::vector<double> mu_of_slot(8);
  for (const auto& row : board.rows)
    mu_of_slot[std::find(g.seats.begin(), g.seats.end(), row.standing.entrant) - g.seats.begin()] =
        row.skill.mu;
  for (size_t a = 0; a < 8; ++a)
    for (size_t b = 0; b < 8; ++b) {
      if (g.places[a] < g.places[b]) {
        EXPECT_GT(mu_of_slot[a], mu_of_slot[b]) << "slots " << a << ", " << b;
      } else if (g.places[a] == g.places[b]) {
        EXPECT_DOUBLE_EQ(mu_of_slot[a], mu_of_slot[b]) << "slots " << a << ", " << b;
      }
    }
  // The table the user sees is that one.
  Process table({program("olympics-league"), "table", "--db", db, "--name", "final", "--json"},
                dir + "/table.log");
  ASSERT_EQ(table.wait(30), 0) << table.output();
  const auto rows = nlohmann::json::parse(table.output());
  ASSERT_EQ(rows.size(), 8u);
  for (size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(rows[i].at("entrant"), board.rows[i].name);
    EXPECT_DOUBLE_EQ(rows[i].at("mu").get<double>(), board.rows[i].skill.mu);
  }
}

std::unique_ptr<Process> heats_of_four(const ServerFixture& server, const std::string& db,
                                       const std::string& log) {
  const LeagueRun heats{db,
                        "heats",
                        "long_jump",
                        "competition_4",
                        R"({"rules": "official", "attempts": 1, "attempt_s": 2})",
                        "",
                        "zero,random:1,zero,random:2,zero,random:3",
                        2,
                        {"--parallel", "1"}};
  return std::make_unique<Process>(league_run_args(heats, server.url(), temp_dir()), log);
}

// Six entrants in heats of four, killed with SIGKILL once a heat is done and resumed: every heat
// played once, in the seats scheduled, to the table of an uninterrupted run.
TEST(RankedLeagueResume, KilledAfterAHeatItResumesToTheSameTable) {
  ServerFixture server;
  const std::string dir = temp_dir();
  auto whole = heats_of_four(server, dir + "/whole.db", dir + "/whole.log");
  ASSERT_EQ(whole->wait(300), 0) << whole->output();

  const std::string db = dir + "/killed.db";
  auto first = heats_of_four(server, db, dir + "/first.log");
  auto done = [&] {
    try {
      int n = 0;
      for (const auto& g : selfplay::LeagueStore(db).games("heats"))
        n += g.status == selfplay::GameStatus::Done;
      return n;
    } catch (const std::exception&) {  // not created yet
      return 0;
    }
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (done() < 1 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  first->signal(SIGKILL);
  first->wait(10);
  selfplay::LeagueStore reference(dir + "/whole.db");
  const auto expected = reference.games("heats");
  ASSERT_GE(expected.size(), 3u) << "six entrants in heats of four: at least three heats";
  ASSERT_GE(done(), 1) << first->output();
  EXPECT_LT(done(), static_cast<int>(expected.size())) << "finished before it was killed";

  auto second = heats_of_four(server, db, dir + "/second.log");
  ASSERT_EQ(second->wait(300), 0) << second->output();
  EXPECT_NE(second->output().find("resuming heats"), std::string::npos);
  selfplay::LeagueStore resumed(db);
  const auto games = resumed.games("heats");
  ASSERT_EQ(games.size(), expected.size());
  for (size_t i = 0; i < games.size(); ++i) {
    EXPECT_EQ(games[i].status, selfplay::GameStatus::Done) << i;
    EXPECT_EQ(games[i].seats, expected[i].seats) << i;
    EXPECT_EQ(games[i].places, expected[i].places) << i;
  }
  const auto a = selfplay::compute_leaderboard(*reference.find_tournament("heats"), expected);
  const auto b = selfplay::compute_leaderboard(*resumed.find_tournament("heats"), games);
  for (size_t i = 0; i < a.rows.size(); ++i) {
    EXPECT_EQ(a.rows[i].name, b.rows[i].name);
    EXPECT_EQ(a.rows[i].skill.mu, b.rows[i].skill.mu);
    EXPECT_EQ(a.rows[i].skill.sigma, b.rows[i].skill.sigma);
    EXPECT_EQ(a.rows[i].standing.played, b.rows[i].standing.played);
  }
}

// Issue 31's 8-athlete hurdles race among them. The scripted baselines are the entrants where
// they make marks, so the heats end in distinct places: four scripted athletes and four zero
// ones (which fall or drop the implement: no mark, last) in the high jump (one try at 0.5 m
// from the event's start: the scripted jumpers walk to the bar, some clear; with one height and
// one try no countback breaks a tie), the long jump (standing, 0.8 m behind the line: the
// scripted jumper's stop), the javelin (a standing throw 2 m behind the arc) and golf (1 m
// putts: the scripted ones drop, the idle ones are picked up at the maximum); eight scripted
// hurdles walkers on seed 32, the league's first seed whose heat has two finishers (the race is
// deterministic per seed; of seeds 1-32, 26 end with all eight out of their lanes, 5 with one
// finisher): places [2,3,1,3,3,3,3,3], times 109.688 and 109.573 s, six out of their lanes.
const std::string kScriptedAndZero =
    "scripted:1,zero,scripted:2,zero,scripted:3,zero,scripted:4,zero";
INSTANTIATE_TEST_SUITE_P(
    Athletics, RankedLeague,
    ::testing::Values(
        RankedSport{"long_jump", R"({"rules": "official", "attempts": 1, "run_up": 0.8})",
                    kScriptedAndZero, 5, Ranking::LongestMark, true},
        RankedSport{"high_jump",
                    R"({"rules": "official", "heights": 1, "tries": 1, "bar_height": 0.5})",
                    kScriptedAndZero, 5, Ranking::LongestMark, true},
        RankedSport{"hurdles", R"({"rules": "official"})",
                    "scripted:1,scripted:2,scripted:3,scripted:4,scripted:5,scripted:6,"
                    "scripted:7,scripted:8",
                    32, Ranking::FastestTime, true},
        RankedSport{"javelin", R"({"rules": "official", "attempts": 1, "run_up": 2})",
                    kScriptedAndZero, 5, Ranking::LongestMark, true},
        RankedSport{"golf", R"({"rules": "official", "distance": 1.0, "hole_s": 12})",
                    kScriptedAndZero, 5, Ranking::FewestStrokes, true}),
    [](const auto& info) { return info.param.sport; });

}  // namespace
}  // namespace olympics::testing
