// The scripted hurdles baseline in process, on the first hurdle: under official rules the walker
// walks its lane and knocks the hurdle over, which is no foul; under the seed's (fixed walls) its
// run ends there. (It does not finish a race yet: docs/athletics.md, "Hurdles".)
#include <gtest/gtest.h>

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
Race walk_until(const nlohmann::json& options, const std::string& call, double seconds) {
  Race r{sport_or_throw("hurdles").create({"solo", 3, 0.0, options}), {}};
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

TEST(HurdlesWalker, PaperItsRunEndsAtTheFirstWall) {
  const Race r = walk_until(nlohmann::json::object(), "did_not_finish", 40);
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events.back()["call"], "did_not_finish");
  EXPECT_EQ(r.events.back()["reason"], "touched_hurdle");
}

}  // namespace
}  // namespace olympics::sports::hurdles
