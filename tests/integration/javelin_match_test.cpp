// The javelin over LCM: a competition of four athletes (each its own team) between two agent
// processes, the scripted thrower in slots 0 and 1, the zero policy in 2 and 3: the throwers'
// valid marks rank them first and second, the two that drop the javelin share third; stored with
// its places and replaying bit for bit.
#include "server_fixture.h"

namespace olympics::testing {
namespace {

TEST(JavelinMatch, ACompetitionOfFourIsRankedByValidMarksAndStored) {
  ServerFixture server;
  const std::vector<std::string> common = {
      "--request-id", "javelin-final",
      "--sport",      "javelin",
      "--mode",       "competition_4",
      "--seed",       "11",
      "--options",    R"({"rules": "official", "run_up": 2, "attempts": 1})"};
  const auto r = server.two_agents(common, {"--slots", "0,1", "--policy", "scripted"},
                                   {"--slots", "2,3", "--policy", "zero"});
  ASSERT_FALSE(r.empty());
  EXPECT_EQ(r.at("reason"), "series_complete") << r.dump();
  auto stored = server.store()->find(r.at("match_id"));
  ASSERT_TRUE(stored.has_value());
  EXPECT_EQ(stored->sport, "javelin");
  ASSERT_EQ(stored->scores.size(), 4u);
  const auto info = nlohmann::json::parse(stored->info);
  const std::vector<int> places = info.at("places");
  ASSERT_EQ(places.size(), 4u) << stored->info;
  EXPECT_LE(places[0], 2) << stored->info;
  EXPECT_LE(places[1], 2) << stored->info;
  EXPECT_EQ(places[2], 3) << stored->info;
  EXPECT_EQ(places[3], 3) << stored->info;
  EXPECT_GT(stored->scores[0], 0.5);
  EXPECT_GT(stored->scores[1], 0.5);
  EXPECT_EQ(stored->scores[2], 0.0);
  const auto check = server::verify_replay(server.replay(r.at("match_id")));
  EXPECT_TRUE(check.identical) << check.report;
}

}  // namespace
}  // namespace olympics::testing
