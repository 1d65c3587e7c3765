#include "soccer/soccer_sport.h"

#include <stdexcept>

namespace olympics::sports::soccer {

SoccerSport::SoccerSport()
    : modes_("soccer",
             {{"penalty_kick", {0}, "one kicker, the ball on the penalty spot, an empty goal"},
              {"penalty_kick_keeper", {0, 1}, "a kicker (team 0) against a goalkeeper (team 1)"},
              {"1v1", {0, 1}, "a match between two players"},
              {"2v2", {0, 0, 1, 1}, "a match between two teams of two"}}) {}

std::vector<SettingSpec> SoccerSport::settings() const {
  // Official: the Laws of the Game (IFAB); the field is Law 1's for international matches.
  return {
      SettingSpec::rules_preset(),
      SettingSpec::number("field_length", 32.0, "m, goal line to goal line (the seed's 32)", 16,
                          110)
          .with_official(105.0),
      SettingSpec::number("field_width", 20.0, "m, touch line to touch line (the seed's 20)", 10,
                          75)
          .with_official(68.0),
      SettingSpec::number("goal_width", 4.0, "m inside the posts (the seed's 4; real 7.32)", 1,
                          7.32)
          .with_official(7.32),
      SettingSpec::number("goal_height", 2.0, "m under the bar (the seed's 2; real 2.44)", 1, 2.44)
          .with_official(2.44),
      SettingSpec::choice("walls", "off",
                          "walls around the field 1.5 m outside the lines (the "
                          "original's), or \"off\" (restarts keep play in)",
                          {"off", "on"}),
      SettingSpec::number("halves", 2, "halves in a match (teams change ends between)", 1, 2),
      SettingSpec::number("half_s", 120.0, "s a half lasts (the match time limit: all halves)", 5,
                          2700)
          .with_official(2700.0),  // Law 7: two halves of 45 minutes
      SettingSpec::choice("touch_line", "throw_in",
                          "a ball over a touch line gives a throw-in, or a free kick 1 m inside",
                          {"throw_in", "free_kick"}),
      SettingSpec::number("restart_distance", 3.0,
                          "m opponents are kept from a restart until it is played (real 9.15)", 0,
                          9.15)
          .with_official(9.15),  // Laws 8, 13, 16, 17
      SettingSpec::number("restart_timeout_s", 10.0,
                          "s after which a restart nobody takes is in play anyway", 1, 60),
      SettingSpec::number("penalty_distance", 11.0,
                          "m from the goal line to the penalty spot (penalty kick modes)", 1, 20),
      SmplMatch::falls_setting("report"),
  };
}

SoccerConfig SoccerSport::config(const nlohmann::json& options) const {
  const nlohmann::json s = merge_settings(name(), settings(), options);
  SoccerConfig c;
  c.field.length = s.at("field_length");
  c.field.width = s.at("field_width");
  c.field.goal_width = s.at("goal_width");
  c.field.goal_height = s.at("goal_height");
  c.field.walls = s.at("walls") == "on";
  c.rules.halves = s.at("halves");
  c.rules.half_s = s.at("half_s");
  c.rules.touch_free_kick = s.at("touch_line") == "free_kick";
  c.rules.restart_distance = s.at("restart_distance");
  c.rules.restart_timeout_s = s.at("restart_timeout_s");
  c.penalty_distance = s.at("penalty_distance");
  c.stand_up = s.at("falls") == "stand_up";
  if (c.field.goal_width + 2 * Field::kGoalArea >= c.field.width)
    throw std::invalid_argument("soccer: goal_width " + std::to_string(c.field.goal_width) +
                                " leaves no room beside the goal area on a field " +
                                std::to_string(c.field.width) + " m wide; widen the field");
  return c;
}

std::unique_ptr<SportMatch> SoccerSport::create(const MatchSettings& settings) const {
  MatchSettings s = settings;
  const SoccerConfig c = config(s.options);
  const ModeSpec& mode = modes_.at(s.mode);
  if (soccer_mode(mode.name) != SoccerMode::TeamPlay &&
      c.penalty_distance > c.field.half_length() - 1)
    throw std::invalid_argument("soccer: penalty_distance " + std::to_string(c.penalty_distance) +
                                " m puts the spot past the centre of a field " +
                                std::to_string(c.field.length) + " m long; shorten it");
  if (s.time_limit_s <= 0)
    s.time_limit_s = soccer_mode(mode.name) == SoccerMode::TeamPlay
                         ? c.rules.halves * c.rules.half_s
                         : kPenaltyKickS;
  return std::make_unique<SoccerMatch>(c, mode, layout(s.mode), s);
}

Layout SoccerSport::layout(const std::string& mode) const {
  const ModeSpec& m = modes_.at(mode);
  const bool team_play = soccer_mode(m.name) == SoccerMode::TeamPlay;
  return smpl_layout(soccer_task_layout(m),
                     team_play ? team_play_rewards() : penalty_kick_rewards(), soccer_calls());
}

}  // namespace olympics::sports::soccer

namespace olympics::sports {
std::unique_ptr<Sport> make_soccer() { return std::make_unique<soccer::SoccerSport>(); }
}  // namespace olympics::sports
