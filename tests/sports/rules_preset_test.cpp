// The `rules` preset every sport has: "paper" (the default: the seed's values) or "official"
// (the rulebook's values, all at once), a setting given beside it still winning; each sport's
// config read both ways.
#include <gtest/gtest.h>

#include "basketball/basketball_sport.h"
#include "boxing/boxing_sport.h"
#include "fencing/fencing_sport.h"
#include "racket/racket_sport.h"
#include "registry.h"
#include "soccer/soccer_sport.h"

namespace olympics::sports {
namespace {

const nlohmann::json kOfficial = {{"rules", "official"}};

const std::vector<std::string> kSports = {"tennis",  "table_tennis", "fencing",   "boxing",
                                          "soccer",  "basketball",   "long_jump", "high_jump",
                                          "javelin", "hurdles",      "golf"};

TEST(RulesPreset, EverySportHasItPaperByDefaultAndItsOfficialValuesAreAllowed) {
  for (const auto& name : kSports) {
    const auto specs = sport_or_throw(name).settings();
    const auto rules = std::find_if(specs.begin(), specs.end(),
                                    [](const SettingSpec& s) { return s.key == "rules"; });
    ASSERT_NE(rules, specs.end()) << name;
    EXPECT_EQ(rules->default_value, "paper") << name;
    const nlohmann::json paper = merge_settings(name, specs, nlohmann::json::object());
    const nlohmann::json official = merge_settings(name, specs, kOfficial);
    for (const auto& s : specs) {
      EXPECT_EQ(paper.at(s.key), s.default_value) << name << " " << s.key;
      if (!s.official) continue;
      EXPECT_NE(*s.official, s.default_value) << name << " " << s.key << ": no difference";
      EXPECT_EQ(official.at(s.key), *s.official) << name << " " << s.key;
      // The official value is one the setting takes when given by itself.
      EXPECT_NO_THROW(merge_settings(name, specs, {{s.key, *s.official}})) << name << " " << s.key;
    }
  }
  EXPECT_THROW(merge_settings("tennis", sport_or_throw("tennis").settings(), {{"rules", "fifa"}}),
               std::invalid_argument);
}

TEST(RulesPreset, TennisNet) {
  const racket::RacketSport tennis(false);
  EXPECT_DOUBLE_EQ(tennis.config("1v1", {}).game.net_height, racket::tennis_game(1.0).net_height);
  EXPECT_DOUBLE_EQ(tennis.config("1v1", kOfficial).game.net_height,
                   racket::tennis_game(0.914).net_height);
  EXPECT_DOUBLE_EQ(
      tennis.config("1v1", {{"rules", "official"}, {"net_height", 1.0}}).game.net_height,
      racket::tennis_game(1.0).net_height)
      << "a setting beside the preset wins";
}

TEST(RulesPreset, TableTennisIsAlreadyOfficial) {
  const racket::RacketSport table_tennis(true);
  EXPECT_DOUBLE_EQ(table_tennis.config("1v1", {}).game.net_height,
                   table_tennis.config("1v1", kOfficial).game.net_height);
}

TEST(RulesPreset, FencingTipForceAndTarget) {
  const fencing::FencingSport f;
  EXPECT_EQ(f.config({}).touch_force_n, 50.0);
  EXPECT_FALSE(f.config({}).whole_body);
  EXPECT_EQ(f.config(kOfficial).touch_force_n, 7.35);
  EXPECT_TRUE(f.config(kOfficial).whole_body);
  EXPECT_EQ(f.config({{"rules", "official"}, {"touch_force_n", 50.0}}).touch_force_n, 50.0);
  EXPECT_TRUE(f.config({{"rules", "official"}, {"touch_force_n", 50.0}}).whole_body);
}

TEST(RulesPreset, BoxingRingAndRounds) {
  const boxing::BoxingSport b;
  EXPECT_EQ(b.config({}).ring.size, 5.0);
  EXPECT_EQ(b.config({}).rules.round_s, 60.0);
  EXPECT_EQ(b.config(kOfficial).ring.size, 6.10);
  EXPECT_EQ(b.config(kOfficial).rules.round_s, 180.0);
  EXPECT_EQ(b.config(kOfficial).rules.rest_s, 60.0);
  EXPECT_EQ(b.config({{"rules", "official"}, {"ring_size", 5.0}}).ring.size, 5.0);
}

TEST(RulesPreset, SoccerFieldGoalsAndHalves) {
  const soccer::SoccerSport s;
  const soccer::SoccerConfig paper = s.config({}), official = s.config(kOfficial);
  EXPECT_EQ(paper.field.goal_width, 4.0);
  EXPECT_EQ(paper.field.goal_height, 2.0);
  EXPECT_EQ(paper.field.length, 32.0);
  EXPECT_EQ(official.field.goal_width, 7.32);
  EXPECT_EQ(official.field.goal_height, 2.44);
  EXPECT_EQ(official.field.length, 105.0);
  EXPECT_EQ(official.field.width, 68.0);
  EXPECT_EQ(official.rules.half_s, 2700.0);
  EXPECT_EQ(official.rules.restart_distance, 9.15);
  EXPECT_EQ(s.config({{"rules", "official"}, {"half_s", 120.0}}).rules.half_s, 120.0);
  // The official field plays: a match is built on it.
  EXPECT_NO_THROW(s.create({"2v2", 1, 5.0, kOfficial}));
}

TEST(RulesPreset, BasketballIsAlreadyOfficial) {
  const basketball::BasketballSport b;
  const basketball::BasketballConfig paper = b.config({}), official = b.config(kOfficial);
  EXPECT_EQ(paper.court.rim_height, official.court.rim_height);
  EXPECT_EQ(paper.court.free_throw_distance, official.court.free_throw_distance);
  EXPECT_EQ(paper.rules.shot_clock_s, official.rules.shot_clock_s);
}

}  // namespace
}  // namespace olympics::sports
