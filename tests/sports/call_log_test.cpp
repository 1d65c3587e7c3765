// olympics-agent --calls: what it prints is the sport's own word (the calls its description
// announces), so every sport's decisions print with no list in the agent; basketball's did not
// when the agent kept one.
#include "call_log.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "registry.h"

namespace olympics::client {
namespace {

std::string info_with(const nlohmann::json& events, const std::string& score) {
  return nlohmann::json{{"events", events}, {"score", {{"text", score}}}}.dump();
}

TEST(CallLog, BasketballAnnouncesItsDecisionsInEveryMode) {
  for (const std::string mode : {"free_throw", "1v1", "2v2"}) {
    const auto announced = announced_calls("basketball", mode);
    ASSERT_TRUE(announced.has_value()) << mode;
    for (const char* call : {"basket", "not_cleared", "miss", "shot_clock", "restart", "out"})
      EXPECT_TRUE(announced->count(call)) << call << " in " << mode;
    EXPECT_FALSE(announced->count("fall")) << "falls are bookkeeping, not decisions";
  }
}

TEST(CallLog, PrintsBasketballsCallsAndLeavesOutTheRest) {
  const auto announced = announced_calls("basketball", "1v1");
  const auto events =
      nlohmann::json::array({{{"call", "fall"}, {"slot", 1}, {"body", "Head"}},
                             {{"call", "basket"}, {"slot", 0}, {"points", 2}, {"team", 0}},
                             {{"call", "shot_clock"}, {"team", 1}},
                             {{"call", "miss"}, {"slot", 0}}});
  const auto lines = call_lines(240, info_with(events, "2-0"), announced);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "tick 240: basket slot 0  2-0");
  EXPECT_EQ(lines[1], "tick 240: shot_clock team 1  2-0");
  EXPECT_EQ(lines[2], "tick 240: miss slot 0  2-0");
}

// A racket point gives its rally's strokes, "stroke" when there was one (the main job's demo).
TEST(CallLog, ARacketPointSaysHowManyStrokesItsRallyHad) {
  const auto announced = announced_calls("table_tennis", "1v1");
  auto point = [](int strokes) {
    return nlohmann::json{
        {"call", "point"}, {"winner_team", 1}, {"reason", "not_over"}, {"strokes", strokes}};
  };
  const auto lines = call_lines(
      64, info_with(nlohmann::json::array({point(0), point(1), point(4)}), "0-1"), announced);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "tick 64: point to team 1 (not_over) after 0 strokes  0-1");
  EXPECT_EQ(lines[1], "tick 64: point to team 1 (not_over) after 1 stroke  0-1");
  EXPECT_EQ(lines[2], "tick 64: point to team 1 (not_over) after 4 strokes  0-1");
}

// The agent's list before the sports announced their own calls: the sports there were then,
// basketball aside, print what they printed then, no more and no less.
TEST(CallLog, OtherSportsAnnounceWhatTheAgentPrintedBefore) {
  const std::set<std::string> printed_before = {
      "point",       "let",  "halt", "knockdown", "up",       "knockout",  "round_end",
      "round_start", "goal", "out",  "restart",   "kick_off", "half_time", "encroachment"};
  for (const std::string name :
       {"sandbox", "tennis", "table_tennis", "fencing", "boxing", "soccer"}) {
    const auto& sport = sports::sport_or_throw(name);
    for (const auto& mode : sport.modes().names()) {
      const auto announced = announced_calls(name, mode);
      ASSERT_TRUE(announced.has_value()) << name << " " << mode;
      for (const auto& call : sport.layout(mode).calls)
        EXPECT_EQ(announced->count(call.name), printed_before.count(call.name))
            << name << " " << mode << ": " << call.name;
    }
  }
}

TEST(CallLog, ASportThisBuildDoesNotKnowShowsEveryCall) {
  EXPECT_FALSE(announced_calls("curling", "1v1").has_value());
  EXPECT_FALSE(announced_calls("basketball", "5v5").has_value());
  const auto lines = call_lines(
      3, info_with(nlohmann::json::array({{{"call", "stone"}, {"slot", 1}}}), "0-0"), std::nullopt);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "tick 3: stone slot 1  0-0");
}

TEST(CallLog, InfoOfAnotherShapePrintsNothing) {
  const auto announced = announced_calls("basketball", "1v1");
  EXPECT_TRUE(call_lines(1, "", announced).empty());
  EXPECT_TRUE(call_lines(1, "not json", announced).empty());
  EXPECT_TRUE(call_lines(1, R"({"events": 3})", announced).empty());
}

}  // namespace
}  // namespace olympics::client
