// The results store, the same checks on SQLite and on a real PostgreSQL server. The PostgreSQL
// half needs OLYMPICS_TEST_POSTGRES_URL (CI starts a server and sets it: .ci/run).
#include "results_store.h"

#include <chrono>
#include <cstdlib>

#include "server_fixture.h"
#include "sql_database.h"

namespace olympics::testing {
namespace {

std::string postgres_url() {
  const char* url = std::getenv("OLYMPICS_TEST_POSTGRES_URL");
  return url ? url : "";
}

std::string unique_prefix() {
  return "t" + std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()) + "-";
}

server::StoredMatch sample(const std::string& id, const std::string& sport, std::int64_t when) {
  server::StoredMatch m;
  m.match_id = id;
  m.server_id = "srv";
  m.server_version = "0.1.0";
  m.sport = sport;
  m.mode = "1v1";
  m.seed = -42;
  m.realtime = true;
  m.ticks = 600;
  m.wall_time_s = 20.5;
  m.reason = "time_limit";
  m.winner_team = 1;
  m.scores = {1.0 / 3.0, 19.9};
  m.info = R"({"events":[]})";
  m.options = R"({"net_height":0.914})";
  m.finished_at_unix = when;
  m.participants = {{0, 0, "alice", "mlp", "v3"}, {1, 1, "bob", "zero", ""}};
  return m;
}

class ResultsStore : public ::testing::TestWithParam<std::string> {};

TEST_P(ResultsStore, RecordsFindsAndListsMatches) {
  if (GetParam() == "postgresql" && postgres_url().empty())
    GTEST_SKIP() << "set OLYMPICS_TEST_POSTGRES_URL (CI does)";
  auto store = server::open_results_store(GetParam() == "postgresql" ? postgres_url()
                                                                     : temp_dir() + "/results.db");
  const std::string p = unique_prefix();
  // Far in the future, and later every run, so these are the newest rows even in a shared database.
  const std::int64_t now = 4'000'000'000 + std::chrono::duration_cast<std::chrono::seconds>(
                                               std::chrono::system_clock::now().time_since_epoch())
                                               .count();
  store->record(sample(p + "a", "sandbox", now));
  store->record(sample(p + "b", "tennis", now + 1));
  auto a = store->find(p + "a");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->seed, -42);
  EXPECT_TRUE(a->realtime);
  EXPECT_EQ(a->ticks, 600);
  EXPECT_EQ(a->winner_team, 1);
  EXPECT_DOUBLE_EQ(a->scores[0], 1.0 / 3.0);  // scores survive the round trip exactly
  EXPECT_EQ(a->info, R"({"events":[]})");
  EXPECT_EQ(a->options, R"({"net_height":0.914})");
  ASSERT_EQ(a->participants.size(), 2u);
  EXPECT_EQ(a->participants[0].policy_version, "v3");
  EXPECT_EQ(a->participants[1].agent, "bob");
  EXPECT_FALSE(store->find(p + "missing"));

  auto recent = store->recent(2, "");
  ASSERT_EQ(recent.size(), 2u);
  EXPECT_EQ(recent[0].match_id, p + "b");  // newest first
  auto tennis = store->recent(10, "tennis");
  ASSERT_FALSE(tennis.empty());
  for (const auto& m : tennis) EXPECT_EQ(m.sport, "tennis");

  // A match id is stored once; a second write fails and leaves the first intact.
  EXPECT_THROW(store->record(sample(p + "a", "sandbox", now)), std::runtime_error);
  EXPECT_EQ(store->find(p + "a")->participants.size(), 2u);
}

INSTANTIATE_TEST_SUITE_P(Backends, ResultsStore, ::testing::Values("sqlite", "postgresql"));

// A results file written before protocol 3 (no options column) opens, keeps its rows, and
// takes new matches with their settings.
TEST(ResultsStoreUpgrade, AStoreWithoutTheOptionsColumnGainsIt) {
  const std::string path = temp_dir() + "/old-results.db";
  {
    auto old = sql::open_sql_database(path);
    old->script(
        "CREATE TABLE matches (match_id TEXT PRIMARY KEY, server_id TEXT NOT NULL, server_version "
        "TEXT NOT NULL, sport TEXT NOT NULL, mode TEXT NOT NULL, seed BIGINT NOT NULL, realtime "
        "INTEGER NOT NULL, ticks INTEGER NOT NULL, wall_time_s DOUBLE PRECISION NOT NULL, reason "
        "TEXT NOT NULL, winner_team INTEGER NOT NULL, scores TEXT NOT NULL, info TEXT NOT NULL, "
        "finished_at_unix BIGINT NOT NULL);"
        "INSERT INTO matches VALUES ('old-1','s','0.1.0','sandbox','1v1',1,0,30,1.0,'time_limit',"
        "-1,'1,1','{}',100);");
  }
  auto store = server::open_results_store(path);
  auto old = store->find("old-1");
  ASSERT_TRUE(old);
  EXPECT_EQ(old->ticks, 30);
  EXPECT_EQ(old->options, "{}");
  store->record(sample("new-1", "tennis", 200));
  EXPECT_EQ(store->find("new-1")->options, R"({"net_height":0.914})");
}

TEST(ResultsStoreErrors, UnreachablePlacesSayWhatToCheck) {
  try {
    server::open_results_store("/nonexistent-dir/results.db");
    ADD_FAILURE();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("check that the folder exists"), std::string::npos)
        << e.what();
  }
  try {
    server::open_results_store("postgresql://nobody:secret@127.0.0.1:1/none?connect_timeout=2");
    ADD_FAILURE();
  } catch (const std::runtime_error& e) {
    std::string what = e.what();
    EXPECT_NE(what.find("cannot connect to postgresql://nobody:***@"), std::string::npos) << what;
    EXPECT_EQ(what.find("secret"), std::string::npos) << "password leaked: " << what;
  }
}

TEST(ResultsStoreServer, ServerWritesMatchesToPostgres) {
  if (postgres_url().empty()) GTEST_SKIP() << "set OLYMPICS_TEST_POSTGRES_URL (CI does)";
  ServerFixture server(std::vector<std::string>{}, unique_lcm_url(), postgres_url());
  const std::string id = unique_prefix() + "pg";
  auto a = server.agent("pg-a", {"--request-id", id, "--slots", "0"});
  auto b = server.agent("pg-b", {"--request-id", id, "--slots", "1"});
  ASSERT_EQ(a->wait(60), 0) << a->output();
  ASSERT_EQ(b->wait(60), 0) << b->output();
  auto r = ServerFixture::agent_result(*a);
  auto stored = server::open_results_store(postgres_url())->find(r.at("match_id"));
  ASSERT_TRUE(stored);
  EXPECT_EQ(stored->ticks, r.at("ticks").get<int>());
  EXPECT_EQ(stored->participants[1].agent, "pg-b");
}

}  // namespace
}  // namespace olympics::testing
