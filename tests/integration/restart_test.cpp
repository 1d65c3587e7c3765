// Restarts lose nothing: a server restarted under the same id gives new match ids (its results
// store and replays keep every match), the matches a crash cut short are recorded as aborted when
// it comes back, clients of a vanished or restarted server fail at once with a clear error, and a
// result that cannot be stored is an error the agents see.
#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>

#include "server_fixture.h"
#include "sql_database.h"

namespace olympics::testing {
namespace {

// An olympics-server process on `url` with the results in `db`, replays beside it.
std::unique_ptr<Process> start_server(const std::string& url, const std::string& dir,
                                      const std::string& db, const std::string& log) {
  auto p = std::make_unique<Process>(
      std::vector<std::string>{program("olympics-server"), "serve", "--lcm-url", url, "--results",
                               db, "--replay-dir", dir + "/replays", "--id", "phoenix"},
      dir + "/" + log);
  EXPECT_TRUE(p->wait_for_output("olympics-server", 60)) << p->output();
  return p;
}

std::unique_ptr<Process> agent(const std::string& url, const std::string& dir,
                               const std::string& name, std::vector<std::string> args) {
  std::vector<std::string> argv = {
      program("olympics-agent"), "--lcm-url", url, "--name", name, "--json", "--timeout", "120"};
  argv.insert(argv.end(), args.begin(), args.end());
  return std::make_unique<Process>(argv, dir + "/" + name + ".log");
}

void play_quick_match(const std::string& url, const std::string& dir, const std::string& id) {
  auto a = agent(url, dir, id + "-a", {"--request-id", id, "--slots", "0", "--time-limit", "1"});
  auto b = agent(url, dir, id + "-b", {"--request-id", id, "--slots", "1", "--time-limit", "1"});
  ASSERT_EQ(a->wait(60), 0) << a->output();
  ASSERT_EQ(b->wait(60), 0) << b->output();
}

TEST(Restart, TheSameServerIdAgainGivesNewMatchIdsAndKeepsEveryResultAndReplay) {
  const std::string url = unique_lcm_url(), dir = temp_dir(), db = dir + "/results.db";
  auto first = start_server(url, dir, db, "first.log");
  play_quick_match(url, dir, "before");
  first->signal(SIGTERM);
  ASSERT_EQ(first->wait(20), 0) << first->output();
  auto second = start_server(url, dir, db, "second.log");
  play_quick_match(url, dir, "after");
  const auto rows = server::open_results_store(db)->recent(10);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_NE(rows[0].match_id, rows[1].match_id);
  for (const auto& m : rows) {
    EXPECT_EQ(m.match_id.rfind("phoenix-", 0), 0u) << m.match_id;
    EXPECT_TRUE(std::filesystem::exists(dir + "/replays/" + m.match_id + ".replay"));
  }
  EXPECT_EQ(second->output().find("UNIQUE"), std::string::npos) << second->output();
}

TEST(Restart, MatchesACrashCutShortAreRecordedAsAbortedWhenTheServerComesBack) {
  const std::string url = unique_lcm_url(), dir = temp_dir(), db = dir + "/results.db";
  auto server = start_server(url, dir, db, "crashed.log");
  // A slow match under way: both agents think 50 ms a tick.
  auto a =
      agent(url, dir, "slow-a",
            {"--request-id", "doomed", "--slots", "0", "--think-ms", "50", "--time-limit", "600"});
  auto b =
      agent(url, dir, "slow-b",
            {"--request-id", "doomed", "--slots", "1", "--think-ms", "50", "--time-limit", "600"});
  ASSERT_TRUE(a->wait_for_output("joined", 30)) << a->output();
  ASSERT_TRUE(b->wait_for_output("joined", 30)) << b->output();
  // The match's scene track (the viewer's data) is written to <match>.scene.part until the
  // match ends: the crash comes once it is.
  auto parts = [&] {
    std::vector<std::string> names;
    for (const auto& f : std::filesystem::directory_iterator(dir + "/replays"))
      if (f.path().string().ends_with(".scene.part")) names.push_back(f.path().filename());
    return names;
  };
  for (int i = 0; i < 300 && parts().empty(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  server->signal(SIGKILL);
  server->wait(10);
  ASSERT_EQ(parts().size(), 1u) << "the crash left the unfinished track";
  std::ofstream(dir + "/replays/phoenix_2-x-1.scene.part") << "another server's";
  // Its agents learn that their server is gone and stop (their own timeout is 120 s).
  EXPECT_EQ(a->wait(60), 2);
  EXPECT_NE(a->output().find("SERVER_GONE"), std::string::npos) << a->output();
  auto back = start_server(url, dir, db, "back.log");
  ASSERT_TRUE(back->wait_for_output("left unfinished as aborted", 10)) << back->output();
  // Coming back, it removes what the crash left of its own matches, and only that.
  EXPECT_EQ(parts(), std::vector<std::string>{"phoenix_2-x-1.scene.part"});
  const auto rows = server::open_results_store(db)->recent(10);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].reason.rfind("aborted: server phoenix stopped", 0), 0u) << rows[0].reason;
  EXPECT_EQ(rows[0].winner_team, -1);
  ASSERT_EQ(rows[0].participants.size(), 2u);
  EXPECT_EQ(rows[0].participants[0].agent, "slow-a");
  EXPECT_EQ(rows[0].participants[1].agent, "slow-b");
}

TEST(Restart, AClientOfARestartedServerFailsAtOnce) {
  const std::string url = unique_lcm_url(), dir = temp_dir(), db = dir + "/results.db";
  auto server = start_server(url, dir, db, "first.log");
  // Alone in a 1v1: it waits for an opponent who never comes.
  auto lonely = agent(url, dir, "lonely", {"--request-id", "alone", "--slots", "0"});
  ASSERT_TRUE(lonely->wait_for_output("joined", 30)) << lonely->output();
  server->signal(SIGKILL);
  server->wait(10);
  auto back = start_server(url, dir, db, "back.log");
  EXPECT_EQ(lonely->wait(60), 2);
  const std::string out = lonely->output();
  EXPECT_TRUE(out.find("SERVER_RESTARTED") != std::string::npos ||
              out.find("UNKNOWN_MATCH") != std::string::npos ||
              out.find("SERVER_GONE") != std::string::npos)
      << out;
}

TEST(Restart, AResultThatCannotBeStoredIsAnErrorTheAgentsSee) {
  ServerFixture server;
  {  // The store will refuse every new match from now on.
    auto db = sql::open_sql_database(server.results_path());
    db->script(
        "CREATE TRIGGER no_room BEFORE INSERT ON matches BEGIN SELECT RAISE(ABORT, 'the disk is "
        "on fire'); END;");
  }
  auto a = server.agent("a", {"--request-id", "unstored", "--slots", "0", "--time-limit", "1"});
  auto b = server.agent("b", {"--request-id", "unstored", "--slots", "1", "--time-limit", "1"});
  EXPECT_EQ(a->wait(60), 2);
  EXPECT_EQ(b->wait(60), 2);
  EXPECT_NE(a->output().find("STORE_FAILED"), std::string::npos) << a->output();
  EXPECT_NE(a->output().find("the disk is on fire"), std::string::npos) << a->output();
}

}  // namespace
}  // namespace olympics::testing
