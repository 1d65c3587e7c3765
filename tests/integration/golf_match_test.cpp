// Golf over LCM: a four-athlete hole (each its own team) between two agent processes, the
// scripted putter in two slots and the zero policy in two: stored with four places (the two
// holed balls share first, the two picked-up balls third), and replaying bit for bit.
#include "server_fixture.h"

namespace olympics::testing {
namespace {

TEST(GolfMatch, AFourAthleteHoleIsStoredWithItsPlacesAndReplays) {
  ServerFixture server;
  const std::vector<std::string> common = {
      "--request-id", "golf-final",
      "--sport",      "golf",
      "--mode",       "competition_4",
      "--seed",       "11",
      "--options",    R"({"rules": "official", "distance": 1.0, "hole_s": 12})"};
  std::vector<std::string> putters = {"--slots", "0,1", "--policy", "scripted"};
  std::vector<std::string> idle = {"--slots", "2,3", "--policy", "zero"};
  const auto r = server.two_agents(common, putters, idle);
  ASSERT_FALSE(r.empty());
  EXPECT_EQ(r.at("reason"), "holes_complete") << r.dump();
  auto stored = server.store()->find(r.at("match_id"));
  ASSERT_TRUE(stored.has_value());
  EXPECT_EQ(stored->sport, "golf");
  ASSERT_EQ(stored->scores.size(), 4u);
  const auto info = nlohmann::json::parse(stored->info);
  // From 1 m both scripted putts drop at the first stroke (deterministic: the official hole
  // draws nothing from the seed); the idle athletes are picked up at the maximum.
  EXPECT_EQ(info.at("places"), (std::vector<int>{1, 1, 3, 3})) << stored->info;
  EXPECT_EQ(stored->scores, (std::vector<double>{1, 1, 6, 6}));
  EXPECT_EQ(r.at("winner_team"), -1) << "first place is shared";
  const auto check = server::verify_replay(server.replay(r.at("match_id")));
  EXPECT_TRUE(check.identical) << check.report;
}

}  // namespace
}  // namespace olympics::testing
