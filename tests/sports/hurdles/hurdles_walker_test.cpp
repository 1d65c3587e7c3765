// The scripted hurdles baseline in process: under official rules the walker pushes hurdles over
// (no foul) and gets on past them; under the seed's (fixed walls) its run ends at the first. (It
// rarely finishes a race: docs/athletics.md, "Hurdles".)
#include <gtest/gtest.h>

#include <cstdio>
#include <set>

#include "core/control_rate.h"
#include "hurdles/hurdles_match.h"
#include "registry.h"
#include "scripted_hurdles.h"

namespace olympics::sports::hurdles {
namespace {

struct Race {
  std::unique_ptr<SportMatch> match;
  std::vector<nlohmann::json> events;
};

// The walker's race until `call` is made (or the race ends), within `seconds`.
Race walk_until(const nlohmann::json& options, const std::string& call, double seconds,
                std::uint64_t seed = 3) {
  Race r{sport_or_throw("hurdles").create({"solo", seed, 0.0, options}), {}};
  client::ScriptedHurdlesPolicy walker;
  walker.start({"hurdles", "solo", core::kControlDt,
                client::ObservationLayout::from_blocks(r.match->layout().observation),
                r.match->action_size()});
  std::vector<float> o(r.match->obs_size()), a(r.match->action_size());
  while (!r.match->outcome().match_over && r.match->tick() < seconds / core::kControlDt) {
    r.match->observe(0, o);
    walker.act(o, a);
    r.match->step({a});
    for (const auto& e : r.match->outcome().info["events"]) r.events.push_back(e);
    if (!r.events.empty() && r.events.back()["call"] == call) break;
  }
  return r;
}

TEST(HurdlesWalker, OfficialItWalksItsLaneAndKnocksTheFirstHurdleOverWithoutAFoul) {
  const Race r = walk_until({{"rules", "official"}}, "knocked", 40);
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events.back()["call"], "knocked") << r.events.back().dump();
  EXPECT_EQ(r.events.back()["hurdle"], 0);
  auto& m = dynamic_cast<HurdlesMatch&>(*r.match);
  EXPECT_FALSE(m.result(0).has_value()) << "still racing after the knock";
}

// Seeds 201-232 were never used to tune it (seeds 1-60 were). The walker before this one (leaning
// its chest into each bar) knocked 9 hurdles over in races 201-216 and never the second one, and
// finished none; this one knocks 56, the second too in 12 races, and finishes race 232.
TEST(HurdlesWalker, OfficialItPushesHurdlesOverAndGetsPastMoreThanTwoARace) {
  int knocked = 0, past_the_first = 0;
  for (std::uint64_t seed = 201; seed <= 216; ++seed) {
    const Race r = walk_until({{"rules", "official"}}, "no call ends this", 120, seed);
    std::set<int> over;
    for (const auto& e : r.events)
      if (e["call"] == "knocked") over.insert(e["hurdle"].get<int>());
    knocked += static_cast<int>(over.size());
    past_the_first += over.count(1);
  }
  std::printf("seeds 201-216: %d hurdles knocked over, the second too in %d races\n", knocked,
              past_the_first);
  EXPECT_GT(knocked, 32) << "hurdles knocked over in 16 races";
  EXPECT_GE(past_the_first, 10) << "races in which the second hurdle went over too";
}

TEST(HurdlesWalker, OfficialItFinishesARaceWithinTheTimeLimit) {
  const Race r = walk_until({{"rules", "official"}}, "finish", 180, 232);
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events.back()["call"], "finish") << r.events.back().dump();
  auto& m = dynamic_cast<HurdlesMatch&>(*r.match);
  ASSERT_TRUE(m.result(0).has_value());
  EXPECT_EQ(m.result(0)->kind, RaceResult::Kind::Finished);
  EXPECT_EQ(m.knocked(0), 10) << "every hurdle pushed over, none passed standing";
  EXPECT_LT(m.result(0)->time, 180.0);
  std::printf("seed 232: finished in %.3f s\n", m.result(0)->time);
}

TEST(HurdlesWalker, PaperItsRunEndsAtTheFirstWall) {
  const Race r = walk_until(nlohmann::json::object(), "did_not_finish", 40);
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events.back()["call"], "did_not_finish");
  EXPECT_EQ(r.events.back()["reason"], "touched_hurdle");
}

}  // namespace
}  // namespace olympics::sports::hurdles
