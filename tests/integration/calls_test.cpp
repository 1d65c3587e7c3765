// olympics-agent --calls between real processes: the referee's decisions print as they happen,
// for any sport whose description announces them (basketball's shot clock never printed while
// the agent kept its own list of calls).
#include "server_fixture.h"

namespace olympics::testing {
namespace {

TEST(AgentCalls, BasketballsShotClockAndRestartsPrintAsTheyHappen) {
  ServerFixture server;
  const std::vector<std::string> common = {
      "--request-id", "calls",  "--sport",  "basketball", "--mode",
      "1v1",          "--seed", "4",        "--options",  R"({"shot_clock_s": 3})",
      "--time-limit", "8",      "--policy", "random",     "--calls"};
  auto first = common, second = common;
  first.insert(first.end(), {"--slots", "0", "--policy-seed", "1"});
  second.insert(second.end(), {"--slots", "1", "--policy-seed", "2"});
  auto a = server.agent("first", first), b = server.agent("second", second);
  ASSERT_EQ(a->wait(300), 0) << a->output();
  ASSERT_EQ(b->wait(300), 0) << b->output();
  // Nobody shoots in 8 s of random play: the 3 s shot clock runs out twice, each time giving
  // the other side a check ball (as tests/integration/basketball_match_test.cpp stores it).
  for (const auto* p : {a.get(), b.get()}) {
    const std::string out = p->output();
    int shot_clocks = 0;
    for (size_t at = out.find(": shot_clock team"); at != std::string::npos;
         at = out.find(": shot_clock team", at + 1))
      ++shot_clocks;
    EXPECT_EQ(shot_clocks, 2) << out;
    EXPECT_NE(out.find(": restart team"), std::string::npos) << out;
    EXPECT_EQ(out.find(": fall"), std::string::npos) << "falls are not announced:\n" << out;
  }
}

}  // namespace
}  // namespace olympics::testing
