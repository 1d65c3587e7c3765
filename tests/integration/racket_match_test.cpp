// Whole tennis and table-tennis matches between two agent processes over LCM, played to their
// final score by the rules and stored with the score and every point in the results database.
#include "server_fixture.h"

namespace olympics::testing {
namespace {

// The scripted baseline against a random policy, which cannot stand and so loses every point by
// falling: the match must run its full format and end "match_won".
nlohmann::json play_to_the_end(ServerFixture& server, const std::string& sport,
                               const std::string& options, const std::string& id) {
  const std::vector<std::string> common = {
      "--request-id", id, "--sport", sport, "--mode", "1v1", "--seed", "4", "--options", options};
  return server.two_agents(common, {"--slots", "0", "--policy", "scripted"},
                           {"--slots", "1", "--policy", "random", "--policy-seed", "2"}, 240);
}

TEST(RacketMatch, FullTennisSetIsPlayedAndStoredWithItsScore) {
  ServerFixture server;
  const auto r = play_to_the_end(server, "tennis", "{}", "tennis-set");
  ASSERT_EQ(r.at("reason"), "match_won") << r.dump();
  EXPECT_EQ(r.at("winner_team"), 0);
  EXPECT_EQ(r.at("scores"), nlohmann::json({1.0, 0.0}));  // sets
  auto stored = server.store()->find(r.at("match_id"));
  ASSERT_TRUE(stored.has_value());
  EXPECT_EQ(stored->sport, "tennis");
  EXPECT_EQ(stored->reason, "match_won");
  const auto info = nlohmann::json::parse(stored->info);
  EXPECT_EQ(info.at("score").at("text"), "6-0");
  EXPECT_EQ(info.at("score").at("winner"), 0);
  EXPECT_GE(info.at("points").size(), 24u);  // six games of at least four points
  for (const auto& p : info.at("points")) EXPECT_TRUE(p.contains("reason")) << p.dump();
}

TEST(RacketMatch, TableTennisGameToElevenIsPlayedAndStored) {
  ServerFixture server;
  const auto r = play_to_the_end(server, "table_tennis", "{\"games_to_win\": 1}", "tt-game");
  ASSERT_EQ(r.at("reason"), "match_won") << r.dump();
  EXPECT_EQ(r.at("winner_team"), 0);
  auto stored = server.store()->find(r.at("match_id"));
  ASSERT_TRUE(stored.has_value());
  const auto info = nlohmann::json::parse(stored->info);
  EXPECT_EQ(info.at("score").at("text"), "11-0");
  EXPECT_EQ(info.at("points").size(), 11u);
}

TEST(RacketMatch, UnknownSettingIsRefusedWithTheKnownOnes) {
  ServerFixture server;
  auto p = server.agent(
      "x", {"--sport", "tennis", "--options", "{\"net_hieght\": 0.9}", "--slots", "0"});
  EXPECT_NE(p->wait(60), 0);
  EXPECT_NE(p->output().find("net_height"), std::string::npos) << p->output();
  auto q = server.agent("y", {"--sport", "tennis", "--options", "[1, 2]", "--slots", "0"});
  EXPECT_NE(q->wait(60), 0);
  EXPECT_NE(q->output().find("JSON object"), std::string::npos) << q->output();
}

}  // namespace
}  // namespace olympics::testing
