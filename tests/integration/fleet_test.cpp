// The league across cells (docs/deploy.md), on a real PostgreSQL (OLYMPICS_TEST_POSTGRES_URL;
// skipped without it, as the other PostgreSQL tests): the queue's leases, expiry and
// stored-once results; cells as real processes with their own servers on private LCM ports
// playing a queued tournament to the table of one host; a cell with another secret, and one whose
// server lacks the tournament's sport, refused with why and the fixtures kept.
// tests/fleet/multi_host_test.sh plays the same across network namespaces with faults.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <thread>

#include "auth.h"
#include "fixture_queue.h"
#include "fleet_snapshots.h"
#include "leaderboard.h"
#include "league_store.h"
#include "mlp_snapshot.h"
#include "sql_database.h"
#include "test_programs.h"

namespace olympics::testing {
namespace {

using selfplay::FixtureQueue;
using selfplay::GameStatus;

std::string postgres_url() {
  const char* url = std::getenv("OLYMPICS_TEST_POSTGRES_URL");
  return url ? url : "";
}

std::string unique_name(const std::string& stem) {
  return stem + std::to_string(std::chrono::system_clock::now().time_since_epoch().count());
}

// `olympics-league run --fleet` for a round robin of four bots; waits for it.
void queue_tournament(const std::string& db, const std::string& name, const std::string& extra_arg,
                      const std::string& secret = "", const std::string& format = "round-robin",
                      const std::string& entrants = "zero,random:1,random:2,zero") {
  std::vector<std::string> argv = {program("olympics-league"),
                                   "run",
                                   "--fleet",
                                   "--db",
                                   db,
                                   "--name",
                                   name,
                                   "--entrants",
                                   entrants,
                                   "--format",
                                   format,
                                   "--seed",
                                   "3",
                                   "--time-limit",
                                   "2"};
  if (!extra_arg.empty()) argv.insert(argv.end(), {"--sport", extra_arg});
  if (!secret.empty()) argv.insert(argv.end(), {"--secret", secret});
  Process queue(argv, temp_dir() + "/queue.log");
  ASSERT_EQ(queue.wait(60), 0) << queue.output();
}

std::unique_ptr<Process> cell(const std::string& db, const std::string& name,
                              const std::string& cell_name, const std::string& secret = "",
                              double lease_s = 30, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> argv = {program("olympics-league"),
                                   "cell",
                                   "--db",
                                   db,
                                   "--name",
                                   name,
                                   "--cell",
                                   cell_name,
                                   "--spawn-server",
                                   "--batch",
                                   "2",
                                   "--lease-s",
                                   std::to_string(lease_s),
                                   "--lcm-url",
                                   unique_lcm_url(),  // a cell-private port: nothing shared
                                   "--log-dir",
                                   temp_dir(),
                                   "--server-wait-s",
                                   "30"};
  if (!secret.empty()) argv.insert(argv.end(), {"--secret", secret});
  argv.insert(argv.end(), extra.begin(), extra.end());
  return std::make_unique<Process>(argv, temp_dir() + "/" + cell_name + ".log");
}

TEST(FleetQueue, LeasesAreDisjointExpireBackToTheQueueAndAResultIsStoredOnce) {
  const std::string url = postgres_url();
  if (url.empty()) GTEST_SKIP() << "set OLYMPICS_TEST_POSTGRES_URL (CI does)";
  const std::string name = unique_name("queue");
  queue_tournament(url, name, "");  // six games
  FixtureQueue a(url, "cell-a"), b(url, "cell-b");
  auto leased_a = a.lease(name, "", 4, 30);
  auto leased_b = b.lease(name, "", 4, 0.5);
  ASSERT_EQ(leased_a.size(), 4u);
  ASSERT_EQ(leased_b.size(), 2u) << "b gets what a did not lease";
  std::set<int> all(leased_a.begin(), leased_a.end());
  all.insert(leased_b.begin(), leased_b.end());
  EXPECT_EQ(all.size(), 6u) << "no fixture leased twice";
  EXPECT_TRUE(a.lease(name, "", 4, 30).empty()) << "nothing left while the leases hold";
  // b's half-second lease runs out: its fixtures are a's to take; a's own still hold.
  std::this_thread::sleep_for(std::chrono::milliseconds(1200));
  auto retaken = a.lease(name, "", 8, 30);
  EXPECT_EQ(retaken, leased_b);
  EXPECT_EQ(b.renew(name, 30), 0) << "b lost its leases to a";
  EXPECT_EQ(a.renew(name, 30), 6);
  // The same fixture's result from both cells (b finished it late): stored once, the first.
  const selfplay::FinishedFixture first{leased_b[0], "a-1", 1.0, "time", 100};
  const selfplay::FinishedFixture late{leased_b[0], "b-7", 1.0, "time", 100};
  EXPECT_TRUE(a.store_result(name, first));
  EXPECT_FALSE(b.store_result(name, late));
  selfplay::LeagueStore store(url);
  auto games = store.games(name);
  EXPECT_EQ(games[leased_b[0]].status, GameStatus::Done);
  EXPECT_EQ(games[leased_b[0]].match_id, "a-1");
  EXPECT_EQ(a.unfinished(name), 5);
  // Another secret is refused by the queue, saying so.
  try {
    a.lease(name, "0123456789abcdef", 1, 30);
    ADD_FAILURE() << "a cell with another secret leased fixtures";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("refuses cell cell-a: its secret"), std::string::npos)
        << e.what();
  }
  // One machine needs no queue: SQLite is refused with what to use instead.
  EXPECT_THROW(FixtureQueue(temp_dir() + "/league.db", "x"), std::invalid_argument);
}

// A tournament with a snapshot entrant queued for the fleet: the file's bytes are in the
// database, and a cell's cache gets exactly those bytes, under its own path.
TEST(FleetQueue, ASnapshotEntrantTravelsThroughTheDatabaseByteForByte) {
  const std::string url = postgres_url();
  if (url.empty()) GTEST_SKIP() << "set OLYMPICS_TEST_POSTGRES_URL (CI does)";
  const std::string name = unique_name("snap"), dir = temp_dir();
  const std::string file = dir + "/policy-v4.safetensors";
  write_snapshot(file, 4);
  queue_tournament(url, name, "", "", "round-robin", "zero,mlp:" + file);
  auto read = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  FixtureQueue queue(url, "check");
  ASSERT_EQ(queue.snapshot_policies(name), std::vector<std::string>{"mlp:" + file});
  EXPECT_EQ(queue.snapshot(name, "mlp:" + file), read(file));
  const auto spec = *selfplay::LeagueStore(url).find_tournament(name);
  const auto local = selfplay::fetch_snapshots(queue, spec, dir + "/cache");
  ASSERT_EQ(local.size(), 1u);
  EXPECT_NE(local.at("mlp:" + file), file);
  EXPECT_EQ(read(local.at("mlp:" + file)), read(file));
}

TEST(Fleet, TwoCellsPlayAQueuedTournamentToTheTableOfOneHost) {
  const std::string url = postgres_url();
  if (url.empty()) GTEST_SKIP() << "set OLYMPICS_TEST_POSTGRES_URL (CI does)";
  const std::string name = unique_name("fleet"), dir = temp_dir();
  // The same tournament on one host: one server, the league playing from SQLite.
  const std::string lcm = unique_lcm_url();
  Process server({program("olympics-server"), "serve", "--id", "solo", "--lcm-url", lcm,
                  "--results", dir + "/solo.db"},
                 dir + "/solo.log");
  Process one({program("olympics-league"), "run", "--db", dir + "/one.db", "--name", "one",
               "--entrants", "zero,random:1,random:2,zero", "--seed", "3", "--time-limit", "2",
               "--lcm-url", lcm, "--log-dir", dir, "--quiet"},
              dir + "/one.log");
  ASSERT_EQ(one.wait(120), 0) << one.output();

  queue_tournament(url, name, "");
  auto c1 = cell(url, name, "cell-1"), c2 = cell(url, name, "cell-2");
  ASSERT_EQ(c1->wait(120), 0) << c1->output();
  ASSERT_EQ(c2->wait(120), 0) << c2->output();

  selfplay::LeagueStore single(dir + "/one.db"), fleet(url);
  auto games = fleet.games(name);
  ASSERT_EQ(games.size(), 6u);
  std::set<std::string> cells;
  for (const auto& g : games) {
    EXPECT_EQ(g.status, GameStatus::Done);
    cells.insert(g.server_id);
  }
  EXPECT_EQ(cells.size(), 2u) << "both cells should have played";
  auto board_one =
      selfplay::compute_leaderboard(*single.find_tournament("one"), single.games("one"));
  auto board_fleet = selfplay::compute_leaderboard(*fleet.find_tournament(name), games);
  ASSERT_EQ(board_one.rows.size(), board_fleet.rows.size());
  for (size_t i = 0; i < board_one.rows.size(); ++i) {
    EXPECT_EQ(board_one.rows[i].name, board_fleet.rows[i].name);
    EXPECT_EQ(board_one.rows[i].standing.points, board_fleet.rows[i].standing.points);
    EXPECT_EQ(board_one.rows[i].skill.mu, board_fleet.rows[i].skill.mu);  // bit for bit
  }
}

// A swiss: each later round is queued by the cell that finds the round before it over; byes
// included (five entrants), the same table as on one host.
TEST(Fleet, ACellQueuesTheLaterRoundsOfASwissToTheTableOfOneHost) {
  const std::string url = postgres_url();
  if (url.empty()) GTEST_SKIP() << "set OLYMPICS_TEST_POSTGRES_URL (CI does)";
  const std::string name = unique_name("swiss"), dir = temp_dir(), lcm = unique_lcm_url();
  const std::string entrants = "zero,random:1,random:2,zero,random:3";
  Process server({program("olympics-server"), "serve", "--id", "solo", "--lcm-url", lcm,
                  "--results", dir + "/solo.db"},
                 dir + "/solo.log");
  Process one({program("olympics-league"), "run", "--db", dir + "/one.db", "--name", "one",
               "--format", "swiss", "--entrants", entrants, "--seed", "3", "--time-limit", "2",
               "--lcm-url", lcm, "--log-dir", dir, "--quiet"},
              dir + "/one.log");
  ASSERT_EQ(one.wait(120), 0) << one.output();
  queue_tournament(url, name, "", "", "swiss", entrants);
  EXPECT_EQ(FixtureQueue(url, "check").unfinished(name), 2) << "round one: two games, a bye";
  auto c = cell(url, name, "swiss-cell");
  ASSERT_EQ(c->wait(120), 0) << c->output();
  selfplay::LeagueStore single(dir + "/one.db"), fleet(url);
  auto games = fleet.games(name);
  ASSERT_EQ(games.size(), single.games("one").size());
  for (const auto& g : games) EXPECT_EQ(g.status, GameStatus::Done);
  auto board_one =
      selfplay::compute_leaderboard(*single.find_tournament("one"), single.games("one"));
  auto board_fleet = selfplay::compute_leaderboard(*fleet.find_tournament(name), games);
  for (size_t i = 0; i < board_one.rows.size(); ++i) {
    EXPECT_EQ(board_one.rows[i].name, board_fleet.rows[i].name);
    EXPECT_EQ(board_one.rows[i].standing.points, board_fleet.rows[i].standing.points);
    EXPECT_EQ(board_one.rows[i].skill.mu, board_fleet.rows[i].skill.mu);
  }
}

TEST(Fleet, ACellWithAnotherSecretIsRefusedAndSaysSo) {
  const std::string url = postgres_url();
  if (url.empty()) GTEST_SKIP() << "set OLYMPICS_TEST_POSTGRES_URL (CI does)";
  const std::string dir = temp_dir(), name = unique_name("secret");
  protocol::write_new_secret(dir + "/deployment.secret");
  protocol::write_new_secret(dir + "/other.secret");
  queue_tournament(url, name, "", dir + "/deployment.secret");
  auto wrong = cell(url, name, "intruder", dir + "/other.secret");
  EXPECT_EQ(wrong->wait(60), 2);
  EXPECT_NE(wrong->output().find("the queue refuses cell intruder: its secret"), std::string::npos)
      << wrong->output();
  EXPECT_EQ(FixtureQueue(url, "check").unfinished(name), 6) << "nothing taken by the intruder";
}

TEST(Fleet, ACellTheDatabaseRefusesExitsSayingWhyAndOneThatCannotReachItWaits) {
  const std::string url = postgres_url();
  if (url.empty()) GTEST_SKIP() << "set OLYMPICS_TEST_POSTGRES_URL (CI does)";
  // Another password (the test URL's user with a wrong one): refused at once, with the reason.
  const std::regex password("://([^:@/]+)(:[^@/]*)?@");
  const std::string wrong = std::regex_replace(url, password, "://$1:not-the-password@");
  auto refused = cell(wrong, "any", "wrong-password");
  EXPECT_EQ(refused->wait(30), 2);
  EXPECT_NE(refused->output().find("the database refuses cell wrong-password"), std::string::npos)
      << refused->output();
  // No database there (yet): the cell waits for it, saying so, rather than exiting.
  auto waiting = cell("postgresql://olympics@127.0.0.1:1/none", "any", "early");
  EXPECT_TRUE(waiting->wait_for_output("cannot reach the database", 30)) << waiting->output();
  EXPECT_TRUE(waiting->running());
}

// A cell for every queued tournament (a Deployment's) plays those it can and leaves the others to
// other cells, saying why, rather than stopping at the first it cannot play. In a schema of its
// own, so that other tests' tournaments are not among "every".
TEST(Fleet, ACellForEveryTournamentPlaysThoseItCanAndSkipsTheOthersSayingWhy) {
  const std::string base = postgres_url();
  if (base.empty()) GTEST_SKIP() << "set OLYMPICS_TEST_POSTGRES_URL (CI does)";
  const std::string schema = unique_name("fleet_every_"), dir = temp_dir();
  sql::open_sql_database(base)->script("CREATE SCHEMA " + schema);
  const std::string url = base + (base.find('?') == std::string::npos ? "?" : "&") +
                          "options=-csearch_path%3D" + schema;
  protocol::write_new_secret(dir + "/other.secret");
  queue_tournament(url, "playable", "", "", "round-robin", "zero,random:1,zero");
  queue_tournament(url, "curling", "curling");
  queue_tournament(url, "other-secret", "", dir + "/other.secret");
  auto every = std::make_unique<Process>(
      std::vector<std::string>{program("olympics-league"), "cell", "--db", url, "--cell", "every",
                               "--spawn-server", "--lcm-url", unique_lcm_url(), "--log-dir", dir,
                               "--server-wait-s", "30"},
      dir + "/every.log");
  EXPECT_EQ(every->wait(120), 2) << every->output();
  const std::string out = every->output();
  EXPECT_NE(out.find("skips tournament curling: no server hosts the sport \"curling\""),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("skips tournament other-secret: the queue refuses cell every"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("no work left it can play (2 tournament(s) refused)"), std::string::npos)
      << out;
  FixtureQueue queue(url, "check");
  EXPECT_EQ(queue.unfinished("playable"), 0) << "the playable tournament was played";
  EXPECT_EQ(queue.unfinished("curling"), 6);
  EXPECT_EQ(queue.unfinished("other-secret"), 6);
}

TEST(Fleet, AFixtureForASportTheCellDoesNotHostIsRefusedByNameAndKept) {
  const std::string url = postgres_url();
  if (url.empty()) GTEST_SKIP() << "set OLYMPICS_TEST_POSTGRES_URL (CI does)";
  const std::string name = unique_name("sport");
  queue_tournament(url, name, "curling");
  auto c = cell(url, name, "no-curling");
  EXPECT_EQ(c->wait(90), 2);
  EXPECT_NE(c->output().find("no server hosts the sport \"curling\""), std::string::npos)
      << c->output();
  FixtureQueue queue(url, "check");
  EXPECT_EQ(queue.unfinished(name), 6) << "the fixtures are kept";
  auto refusals = queue.refusals(name);
  ASSERT_EQ(refusals.size(), 1u);
  EXPECT_NE(refusals[0].find("no-curling: no server hosts the sport \"curling\""),
            std::string::npos)
      << refusals[0];
  // Back in the queue at once (not held until the lease runs out): another cell may lease them.
  EXPECT_EQ(queue.lease(name, "", 10, 30).size(), 6u);
}

// The self-play options both runs below share: PFSP of the latest snapshot over a window and two
// bots, 12 games, decisions lagging 3 games (--parallel 3).
std::vector<std::string> selfplay_argv(const std::string& db, const std::string& name,
                                       const std::string& snapshots,
                                       const std::vector<std::string>& extra = {}) {
  std::vector<std::string> argv = {program("olympics-league"),
                                   "selfplay",
                                   "--db",
                                   db,
                                   "--name",
                                   name,
                                   "--snapshots",
                                   snapshots,
                                   "--window",
                                   "2",
                                   "--bots",
                                   "zero,random:4",
                                   "--strategy",
                                   "pfsp:hard",
                                   "--bot-share",
                                   "0.2",
                                   "--matches",
                                   "12",
                                   "--parallel",
                                   "3",
                                   "--seed",
                                   "9",
                                   "--time-limit",
                                   "4"};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return argv;
}

// Polls `query` (one count) on the fleet's database until it reaches `at_least`.
bool wait_for_count(sql::SqlDatabase& db, const std::string& query,
                    const std::vector<std::string>& params, int at_least, double timeout_s = 120) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    if (std::stoi(db.query(query, params)[0][0]) >= at_least) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

// Self-play over three cells: its scheduler (selfplay --fleet) queues each game once the results
// it depends on are stored. The scheduler is killed with SIGKILL and started again, one cell is
// killed holding a game, the snapshots' folder is gone once the run started (cells play the
// copies the database holds): every game is stored once, and the games, their results and the
// table are those of the same run on one host.
TEST(Fleet, SelfplayOverThreeCellsDecidesAsOneHostThroughAKilledSchedulerAndCell) {
  const std::string url = postgres_url();
  if (url.empty()) GTEST_SKIP() << "set OLYMPICS_TEST_POSTGRES_URL (CI does)";
  const std::string name = unique_name("selfplay"), dir = temp_dir();
  const std::string snapshots = dir + "/snapshots", lcm = unique_lcm_url();
  std::filesystem::create_directories(snapshots);
  for (int v = 1; v <= 3; ++v)
    write_snapshot(snapshots + "/policy-v" + std::to_string(v) + ".safetensors", v);

  // The run on one host: one server, the league from SQLite.
  Process server({program("olympics-server"), "serve", "--id", "solo", "--capacity", "3",
                  "--lcm-url", lcm, "--results", dir + "/solo.db"},
                 dir + "/solo.log");
  auto one_argv = selfplay_argv(dir + "/one.db", "one", snapshots);
  one_argv.insert(one_argv.end(), {"--lcm-url", lcm, "--log-dir", dir, "--quiet"});
  Process one(one_argv, dir + "/one.log");
  ASSERT_EQ(one.wait(180), 0) << one.output();

  // The fleet: the scheduler and three cells of one game at a time each.
  auto db = sql::open_sql_database(url);
  FixtureQueue(url, "check");  // the queue's tables, for the polls below
  auto scheduler = std::make_unique<Process>(
      selfplay_argv(url, name, snapshots, {"--fleet", "--quiet"}), dir + "/scheduler1.log");
  ASSERT_TRUE(wait_for_count(*db, "SELECT count(*) FROM fleet_snapshots WHERE tournament = $1",
                             {name}, 3, 60))
      << scheduler->output();
  // Its snapshots are stored: the learner's folder is of no use to the cells from now on.
  std::filesystem::rename(snapshots, dir + "/snapshots-elsewhere");
  std::vector<std::unique_ptr<Process>> cells;
  for (const char* c : {"sp-1", "sp-2", "sp-3"})
    cells.push_back(cell(url, name, c, "", 3, {"--parallel", "1"}));

  const std::string done = "SELECT count(*) FROM fleet_results WHERE tournament = $1";
  ASSERT_TRUE(wait_for_count(*db, done, {name}, 3)) << scheduler->output();
  scheduler->signal(SIGKILL);
  scheduler->wait(10);
  scheduler = std::make_unique<Process>(selfplay_argv(url, name, snapshots, {"--fleet"}),
                                        dir + "/scheduler2.log");
  // sp-2 dies holding a game it leased (starting or playing it).
  ASSERT_TRUE(wait_for_count(*db,
                             "SELECT count(*) FROM games g JOIN fleet_queue q ON q.tournament = "
                             "g.tournament AND q.idx = g.idx WHERE g.tournament = $1 AND "
                             "q.cell = 'sp-2' AND q.state = 'leased'",
                             {name}, 1))
      << cells[1]->output();
  const auto held = db->query(
      "SELECT idx FROM fleet_queue WHERE tournament = $1 AND cell = 'sp-2' AND state = 'leased'",
      {name});
  cells[1]->signal(SIGKILL);
  cells[1]->wait(10);

  ASSERT_EQ(scheduler->wait(240), 0) << scheduler->output();
  EXPECT_NE(scheduler->output().find("resuming " + name), std::string::npos) << scheduler->output();
  for (int c : {0, 2}) EXPECT_EQ(cells[c]->wait(60), 0) << cells[c]->output();

  // Every game stored exactly once, the killed cell's game by another cell.
  EXPECT_EQ(db->query("SELECT count(*), count(DISTINCT idx) FROM fleet_results WHERE "
                      "tournament = $1",
                      {name})[0],
            (sql::SqlDatabase::Row{"12", "12"}));
  for (const auto& row : held)
    EXPECT_NE(db->query("SELECT cell FROM fleet_results WHERE tournament = $1 AND idx = $2",
                        {name, row[0]})[0][0],
              "sp-2")
        << "game " << row[0] << " was sp-2's when it was killed";
  EXPECT_FALSE(held.empty()) << "sp-2 held no game when it was killed";

  selfplay::LeagueStore single(dir + "/one.db"), fleet(url);
  auto ga = single.games("one"), gb = fleet.games(name);
  ASSERT_EQ(ga.size(), 12u);
  ASSERT_EQ(gb.size(), 12u);
  auto sa = *single.find_tournament("one"), sb = *fleet.find_tournament(name);
  std::set<std::string> cells_that_played;
  for (size_t i = 0; i < ga.size(); ++i) {
    EXPECT_EQ(sa.entrants[ga[i].home].name, sb.entrants[gb[i].home].name) << "game " << i;
    EXPECT_EQ(sa.entrants[ga[i].away].name, sb.entrants[gb[i].away].name) << "game " << i;
    EXPECT_EQ(ga[i].home_score, gb[i].home_score) << "game " << i;
    EXPECT_EQ(ga[i].ticks, gb[i].ticks) << "game " << i;
    cells_that_played.insert(gb[i].server_id);
  }
  EXPECT_GE(cells_that_played.size(), 2u);
  auto ta = selfplay::compute_leaderboard(sa, ga), tb = selfplay::compute_leaderboard(sb, gb);
  ASSERT_EQ(ta.rows.size(), tb.rows.size());
  for (size_t i = 0; i < ta.rows.size(); ++i) {
    EXPECT_EQ(ta.rows[i].name, tb.rows[i].name);
    EXPECT_EQ(ta.rows[i].skill.mu, tb.rows[i].skill.mu);  // bit for bit
  }
}

// A live learner plays on its own host's LCM, which cells do not share: refused with what to do.
TEST(Fleet, SelfplayWithALiveLearnerIsRefusedWithWhatToDo) {
  const std::string url = postgres_url();
  if (url.empty()) GTEST_SKIP() << "set OLYMPICS_TEST_POSTGRES_URL (CI does)";
  auto argv = selfplay_argv(url, unique_name("live"), temp_dir() + "/none");
  argv.insert(argv.end(), {"--fleet", "--learner", "alice"});
  Process refused(argv, temp_dir() + "/live.log");
  EXPECT_EQ(refused.wait(30), 2);
  EXPECT_NE(refused.output().find("a live learner (--learner) plays on its own host's LCM"),
            std::string::npos)
      << refused.output();
}

}  // namespace
}  // namespace olympics::testing
