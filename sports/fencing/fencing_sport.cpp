#include "fencing/fencing_sport.h"

#include <stdexcept>

#include "combat/combat_rewards.h"

namespace olympics::sports::fencing {

FencingSport::FencingSport() : modes_("fencing", {{"1v1", {0, 1}, "a bout between two fencers"}}) {}

std::vector<SettingSpec> FencingSport::settings() const {
  return {
      SettingSpec::rules_preset(),
      SettingSpec::number("touches", 5, "touches that win the bout (direct elimination: 15)", 1,
                          45),
      SettingSpec::number("touch_force_n", 50.0,
                          "N: the tip's contact force that registers (the seed's 50; a real "
                          "épée tip fires at 7.35)",
                          1, 2000)
          .with_official(7.35),  // FIE Material Rules: the tip's spring holds 750 g
      SettingSpec::number("double_window_s", 0.04,
                          "s: a touch by the other fencer this soon after the first is a double", 0,
                          0.2),
      SettingSpec::choice("target", "torso",
                          "pelvis, torso, spine, chest and head (the seed's), or \"whole_body\" "
                          "(épée's rule)",
                          {"torso", "whole_body"})
          .with_official("whole_body"),  // FIE Technical Rules: épée's target is the whole body
      SettingSpec::choice("fall_penalty", "halt",
                          "a fall only halts play (épée's rule), or gives the opponent a touch "
                          "(a shaping penalty of this project's, not a rule)",
                          {"halt", "touch"}),
      SettingSpec::number("idle_s", 60.0, "s without a touch: play halts (non-combativity)", 5,
                          600),
      SettingSpec::number("piste_length", 14.0, "m (the seed's 14)", 6, 30),
      SettingSpec::number("piste_width", 2.0, "m (the seed's 2; real 1.5-2)", 1, 4),
      SettingSpec::number("on_guard_m", 2.0, "m from the centre line to each on-guard line", 0.75,
                          5),
  };
}

FencingConfig FencingSport::config(const nlohmann::json& options) const {
  const nlohmann::json s = merge_settings(name(), settings(), options);
  FencingConfig c;
  c.rules.touches = s.at("touches");
  c.rules.double_window_s = s.at("double_window_s");
  c.rules.fall_penalty = s.at("fall_penalty") == "touch" ? FallPenalty::Touch : FallPenalty::Halt;
  c.rules.idle_s = s.at("idle_s");
  c.piste.length = s.at("piste_length");
  c.piste.width = s.at("piste_width");
  c.piste.on_guard = s.at("on_guard_m");
  c.touch_force_n = s.at("touch_force_n");
  c.whole_body = s.at("target") == "whole_body";
  if (c.piste.on_guard > c.piste.length / 2 - 1)
    throw std::invalid_argument(
        "fencing setting \"on_guard_m\" must leave 1 m behind each line: "
        "at most piste_length / 2 - 1 = " +
        std::to_string(c.piste.length / 2 - 1));
  return c;
}

std::unique_ptr<SportMatch> FencingSport::create(const MatchSettings& settings) const {
  MatchSettings s = settings;
  if (s.time_limit_s <= 0) s.time_limit_s = default_time_limit_s();
  return std::make_unique<FencingMatch>(config(s.options), modes_.at(s.mode), layout(s.mode), s);
}

Layout FencingSport::layout(const std::string& mode) const {
  modes_.at(mode);
  return smpl_layout(fencing_task_layout(), combat::combat_rewards("the épée's tip"),
                     fencing_calls());
}

}  // namespace olympics::sports::fencing

namespace olympics::sports {
std::unique_ptr<Sport> make_fencing() { return std::make_unique<fencing::FencingSport>(); }
}  // namespace olympics::sports
