// Basketball over LCM: a 1v1 between two agent processes played to its time limit under a short
// shot clock, stored with its score and the rule calls that were made, replaying bit for bit.
#include "server_fixture.h"

namespace olympics::testing {
namespace {

TEST(BasketballMatch, A1v1BetweenTwoAgentProcessesIsStoredWithItsScoreAndReplays) {
  ServerFixture server;
  const std::vector<std::string> common = {
      "--request-id", "pickup", "--sport",  "basketball", "--mode",
      "1v1",          "--seed", "4",        "--options",  R"({"shot_clock_s": 3})",
      "--time-limit", "8",      "--policy", "random"};
  const auto r = server.two_agents(common, {"--slots", "0", "--policy-seed", "1"},
                                   {"--slots", "1", "--policy-seed", "2"});
  ASSERT_FALSE(r.empty());
  EXPECT_EQ(r.at("reason"), "time_limit") << r.dump();
  auto stored = server.store()->find(r.at("match_id"));
  ASSERT_TRUE(stored.has_value());
  EXPECT_EQ(stored->sport, "basketball");
  EXPECT_EQ(stored->mode, "1v1");
  ASSERT_EQ(stored->participants.size(), 2u);
  const auto info = nlohmann::json::parse(stored->info);
  EXPECT_EQ(info.at("score").at("text"), "0-0") << stored->info;
  // Nobody shoots in 8 s of random play: the 3 s shot clock runs out twice, each time giving
  // the other side a check ball.
  EXPECT_EQ(info.at("stoppages"), nlohmann::json({{"shot_clock", 2}})) << stored->info;
  EXPECT_TRUE(info.at("baskets").empty());
  const auto check = server::verify_replay(server.replay(r.at("match_id")));
  EXPECT_TRUE(check.identical) << check.report;
}

TEST(BasketballMatch, ScriptedTeamPlayersInTwoAgentProcessesShootAndTheMatchReplays) {
  // `--policy scripted` in 1v1 is the team player (clients/agent/scripted_basketball_team.h):
  // the check ball's taker shoots (from 7.5 m, beyond the set shot's reach: the long shot, which
  // goes in or comes off the rim and bounces out), the other side takes the next ball, and so on.
  ServerFixture server;
  const std::vector<std::string> common = {"--request-id", "scripted", "--sport",  "basketball",
                                           "--mode",       "1v1",      "--seed",   "1",
                                           "--time-limit", "10",       "--policy", "scripted"};
  const auto r = server.two_agents(common, {"--slots", "0"}, {"--slots", "1"});
  ASSERT_FALSE(r.empty());
  EXPECT_EQ(r.at("reason"), "time_limit") << r.dump();
  auto stored = server.store()->find(r.at("match_id"));
  ASSERT_TRUE(stored.has_value());
  const auto info = nlohmann::json::parse(stored->info);
  // A shot that went out (random players never shoot: the test above).
  EXPECT_GE(info.at("stoppages").value("out", 0), 1) << stored->info;
  const auto check = server::verify_replay(server.replay(r.at("match_id")));
  EXPECT_TRUE(check.identical) << check.report;
}

}  // namespace
}  // namespace olympics::testing
