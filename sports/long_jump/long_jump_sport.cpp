#include "long_jump/long_jump_sport.h"

#include "athletics/competition.h"
#include "long_jump/long_jump_match.h"
#include "long_jump/long_jump_rewards.h"

namespace olympics::sports::long_jump {

LongJumpSport::LongJumpSport()
    : modes_(athletics::field_event_modes("long_jump", "a series of long jumps")) {}

std::vector<SettingSpec> LongJumpSport::settings() const {
  // Official: World Athletics Technical Rules 25 (field events), 29 and 30 (the long jump).
  return {
      SettingSpec::rules_preset(),
      SettingSpec::choice("measure", "paper",
                          "the seed's: a foot past the line starts the jump, the first contact "
                          "after it is the landing, measured at the mean x of all bodies; or "
                          "\"official\": fouls past the line on the ground, the mark to the "
                          "nearest break in the sand",
                          {"paper", "official"})
          .with_official("official"),
      SettingSpec::number("run_up", 20.0,
                          "m from the start mark to the foul line (the athlete's own run-up "
                          "length; 0.5-1: a standing long jump)",
                          0.5, 45),
      SettingSpec::number("runway_width", 1.0, "m (the seed's 1; TR 29.3: 1.22)", 0.5, 1.22)
          .with_official(1.22),
      SettingSpec::number("pit_near", 1.0, "m from the foul line to the pit (TR 29.5: 1 to 3)", 0,
                          3),
      SettingSpec::number("attempts", 1,
                          "attempts per athlete (the seed's episode: 1; TR 25.5: 3 rounds)", 1, 6)
          .with_official(3),
      SettingSpec::number("attempt_s", 20.0, "s an attempt may last (TR 25.17: 1 minute)", 2, 60)
          .with_official(60.0),
  };
}

LongJumpRules LongJumpSport::rules(const nlohmann::json& options) const {
  const nlohmann::json s = merge_settings(name(), settings(), options);
  LongJumpRules r;
  r.official = s.at("measure") == "official";
  r.line_x = s.at("run_up");
  r.goal_x = r.line_x + 10.0;  // the seed's goal: 10 m past its line at 20 m
  r.runway_width = s.at("runway_width");
  r.pit_near = s.at("pit_near");
  r.attempts = s.at("attempts");
  r.attempt_s = s.at("attempt_s");
  return r;
}

std::unique_ptr<SportMatch> LongJumpSport::create(const MatchSettings& settings) const {
  MatchSettings s = settings;
  const LongJumpRules r = rules(s.options);
  if (s.time_limit_s <= 0) s.time_limit_s = r.attempts * r.attempt_s;
  return std::make_unique<LongJumpMatch>(r, modes_.at(s.mode), layout(s.mode), s);
}

Layout LongJumpSport::layout(const std::string& mode) const {
  modes_.at(mode);
  return smpl_layout(long_jump_task_layout(), long_jump_rewards(), long_jump_calls());
}

}  // namespace olympics::sports::long_jump

namespace olympics::sports {
std::unique_ptr<Sport> make_long_jump() { return std::make_unique<long_jump::LongJumpSport>(); }
}  // namespace olympics::sports
