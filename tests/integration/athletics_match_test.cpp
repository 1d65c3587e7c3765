// Athletics over LCM: a long-jump competition of four athletes (each its own team) between two
// agent processes, played to the end of every series, stored with its four places and replaying
// bit for bit; a high-jump competition likewise.
#include "server_fixture.h"

namespace olympics::testing {
namespace {

// Standing on their marks the athletes run out of time on every attempt: every series ends in
// failures, and all four share first place with no mark.
void play_competition(const std::string& sport, const std::string& options) {
  ServerFixture server;
  const std::vector<std::string> common = {"--request-id", sport + "-final", "--sport",  sport,
                                           "--mode",       "competition_4",  "--seed",   "11",
                                           "--options",    options,          "--policy", "zero"};
  const auto r = server.two_agents(common, {"--slots", "0,1"}, {"--slots", "2,3"});
  ASSERT_FALSE(r.empty());
  EXPECT_EQ(r.at("reason"), "series_complete") << r.dump();
  EXPECT_EQ(r.at("winner_team"), -1) << "a four-way tie has no single winner";
  auto stored = server.store()->find(r.at("match_id"));
  ASSERT_TRUE(stored.has_value());
  EXPECT_EQ(stored->sport, sport);
  ASSERT_EQ(stored->participants.size(), 4u);
  ASSERT_EQ(stored->scores.size(), 4u);
  const auto info = nlohmann::json::parse(stored->info);
  EXPECT_EQ(info.at("places"), (std::vector<int>{1, 1, 1, 1})) << stored->info;
  int failures = 0;
  for (const auto& e : info.at("events"))
    if (e.at("call") == "foul" || e.at("call") == "failure") ++failures;
  EXPECT_GE(failures, 1) << "the last tick's events hold at least the last failure";
  const auto check = server::verify_replay(server.replay(r.at("match_id")));
  EXPECT_TRUE(check.identical) << check.report;
}

TEST(AthleticsMatch, ALongJumpCompetitionOfFourIsStoredWithItsPlaces) {
  play_competition("long_jump", R"({"rules": "official", "attempts": 2, "attempt_s": 2})");
}

TEST(AthleticsMatch, AHighJumpCompetitionOfFourIsStoredWithItsPlaces) {
  play_competition("high_jump", R"({"rules": "official", "heights": 2, "tries": 1,
                                    "attempt_s": 2})");
}

}  // namespace
}  // namespace olympics::testing
