#include "basketball/basketball_sport.h"

namespace olympics::sports::basketball {

BasketballSport::BasketballSport()
    : modes_("basketball",
             {{"free_throw",
               {0},
               "one shooter behind the free-throw line, the ball presented between its hands"},
              {"1v1",
               {0, 1},
               "a game between two players (3x3 rules on the half court, or the full court's)"},
              {"2v2",
               {0, 0, 1, 1},
               "a game between two teams of two (3x3 rules on the half court, or the full "
               "court's)"}}) {}

std::vector<SettingSpec> BasketballSport::settings() const {
  // The seed's court, ball and basket are FIBA's, and the game FIBA 3x3's (10 minutes, 21
  // points, a 12 s shot clock): "official" changes nothing.
  return {
      SettingSpec::rules_preset(),
      SettingSpec::number("rim_height", 3.05, "m, the rim above the floor (the original's 2.8)",
                          2.0, 3.5),
      SettingSpec::number("free_throw_distance", 4.6, "m from the backboard's plane to the line",
                          1.0, 8.0),
      SettingSpec::number("present_s", 0.5,
                          "s the ball is held still between the shooter's (or a restart's "
                          "taker's) hands",
                          0, 3),
      SettingSpec::choice("court", "half",
                          "team play: the half court of 3x3 (one basket; 1 and 2 points, the "
                          "ball cleared behind the arc) or the full 28 m court (a basket at "
                          "each end; 2 and 3 points, throw-ins)",
                          {"half", "full"}),
      SettingSpec::number("points_to_win", 21, "team play: the game ends when a side has these", 1,
                          100),
      SettingSpec::number("game_s", 600,
                          "team play: s of game time (the match's default time limit)", 5, 3600),
      SettingSpec::number("shot_clock_s", 12, "team play: s to get a shot to the basket", 3, 60),
      SettingSpec::number("restart_distance", 2.0,
                          "team play: m the defenders stand from a restart's taker", 1, 6),
      SmplMatch::falls_setting("stand_up"),
  };
}

BasketballConfig BasketballSport::config(const nlohmann::json& options) const {
  const nlohmann::json s = merge_settings(name(), settings(), options);
  BasketballConfig c;
  c.court.rim_height = s.at("rim_height");
  c.court.free_throw_distance = s.at("free_throw_distance");
  c.court.full = s.at("court") == "full";
  c.present_s = s.at("present_s");
  c.rules.points_to_win = s.at("points_to_win");
  c.rules.shot_clock_s = s.at("shot_clock_s");
  c.restart_distance = s.at("restart_distance");
  c.game_s = s.at("game_s");
  c.stand_up = s.at("falls") == "stand_up";
  return c;
}

std::unique_ptr<SportMatch> BasketballSport::create(const MatchSettings& settings) const {
  MatchSettings s = settings;
  const BasketballConfig c = config(s.options);
  const ModeSpec& mode = modes_.at(s.mode);
  if (s.time_limit_s <= 0) s.time_limit_s = is_team_play(mode.name) ? c.game_s : kFreeThrowS;
  return std::make_unique<BasketballMatch>(c, mode, layout(s.mode), s);
}

Layout BasketballSport::layout(const std::string& mode) const {
  const ModeSpec& m = modes_.at(mode);
  return humanoid_layout(kHumanoid, basketball_task_layout(m),
                         is_team_play(m.name) ? team_play_rewards() : free_throw_rewards(),
                         basketball_calls());
}

}  // namespace olympics::sports::basketball

namespace olympics::sports {
std::unique_ptr<Sport> make_basketball() { return std::make_unique<basketball::BasketballSport>(); }
}  // namespace olympics::sports
