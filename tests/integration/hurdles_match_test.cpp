// The hurdles over LCM: an 8-athlete race (each its own team) between two agent processes, four
// lanes each, stored with its eight places and replaying bit for bit.
#include "server_fixture.h"

namespace olympics::testing {
namespace {

// Standing at their marks the athletes fall and stay down: every race ends did-not-finish (or,
// a foot over a line while falling, disqualified), so all eight share first place.
TEST(HurdlesMatch, AnEightAthleteRaceIsStoredWithItsPlaces) {
  ServerFixture server;
  const std::vector<std::string> common = {
      "--request-id", "hurdles-final",
      "--sport",      "hurdles",
      "--mode",       "competition_8",
      "--seed",       "12",
      "--options",    R"({"rules": "official", "get_up_s": 1})",
      "--time-limit", "20",
      "--policy",     "zero"};
  const auto r = server.two_agents(common, {"--slots", "0,1,2,3"}, {"--slots", "4,5,6,7"});
  ASSERT_FALSE(r.empty());
  EXPECT_EQ(r.at("reason"), "race_complete") << r.dump();
  EXPECT_EQ(r.at("winner_team"), -1) << "an eight-way tie has no single winner";
  auto stored = server.store()->find(r.at("match_id"));
  ASSERT_TRUE(stored.has_value());
  EXPECT_EQ(stored->sport, "hurdles");
  ASSERT_EQ(stored->participants.size(), 8u);
  ASSERT_EQ(stored->scores.size(), 8u);
  const auto info = nlohmann::json::parse(stored->info);
  EXPECT_EQ(info.at("places"), (std::vector<int>(8, 1))) << stored->info;
  ASSERT_EQ(info.at("results").size(), 8u);
  for (const auto& end : info.at("results")) EXPECT_NE(end, "finished");
  const auto check = server::verify_replay(server.replay(r.at("match_id")));
  EXPECT_TRUE(check.identical) << check.report;
}

}  // namespace
}  // namespace olympics::testing
