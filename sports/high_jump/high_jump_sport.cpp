#include "high_jump/high_jump_sport.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "athletics/competition.h"
#include "high_jump/high_jump_match.h"
#include "high_jump/high_jump_rewards.h"

namespace olympics::sports::high_jump {

HighJumpSport::HighJumpSport()
    : modes_(athletics::field_event_modes("high_jump", "a series of high jumps")) {}

std::vector<SettingSpec> HighJumpSport::settings() const {
  // Official: World Athletics Technical Rules 25 (field events), 26 and 27 (vertical jumps).
  return {
      SettingSpec::rules_preset(),
      SettingSpec::choice("measure", "paper",
                          "the seed's: a clearance is every body 0.1 m past the bar with the bar "
                          "up, an attempt ends on a fall, the bar displaced or leaving the run-up "
                          "area; or \"official\": failures as TR 27.2 has them",
                          {"paper", "official"})
          .with_official("official"),
      SettingSpec::choice(
          "bar", "paper",
          "the seed's crossbar (8 kg, 25 mm radius, 4.1 m on 0.1 m posts) or "
          "\"official\" (TR 27.6: 2 kg, 30 mm round, 4.00 m on 40 x 60 mm supports)",
          {"paper", "official"})
          .with_official("official"),
      SettingSpec::choice("landing_mat", "none",
                          "the seed has none; \"mat\": 6 x 4 x 0.7 m of soft foam behind the bar",
                          {"none", "mat"})
          .with_official("mat"),
      SettingSpec::number("runup_radius", 25.0,
                          "m, official: the fan-shaped run-up, a half disc of this radius in "
                          "front of the bar's centre (TR 27.3: at least 15 m, 25 m at the major "
                          "competitions); leaving it before going over is a failure",
                          15, 60),
      SettingSpec::number("bar_height", 1.0,
                          "m, the first height (the seed trains at 0.5, 1.0, 1.5 and 2.0)", 0.3,
                          2.5),
      SettingSpec::number("bar_raise", 0.0,
                          "m the bar goes up per round (0: one height, the seed's "
                          "episode; TR 26.7: at least 0.02)",
                          0, 0.5)
          .with_official(0.05),
      SettingSpec::number("heights", 1, "heights in the series (the last ends it)", 1, 40)
          .with_official(10),
      SettingSpec::number("tries", 1, "tries at each height (the seed: 1; TR 26.4: 3)", 1, 3)
          .with_official(3),
      SettingSpec::number("attempt_s", 20.0, "s an attempt may last (TR 25.17: 1 minute)", 2, 60)
          .with_official(60.0),
  };
}

HighJumpRules HighJumpSport::rules(const nlohmann::json& options) const {
  const nlohmann::json s = merge_settings(name(), settings(), options);
  HighJumpRules r;
  r.official = s.at("measure") == "official";
  if (s.at("bar") == "official") {
    r.bar_length = 4.0, r.bar_radius = 0.015, r.bar_mass = 2.0;
    r.support_depth = 0.04, r.support_length = 0.06;
  }
  r.landing_mat = s.at("landing_mat") == "mat";
  r.runup_radius = s.at("runup_radius");
  const double start_distance = std::hypot(r.bar_x, r.bar_y);  // the start mark's, from the bar
  if (r.official && r.runup_radius < start_distance)
    throw std::invalid_argument("high_jump: runup_radius " + std::to_string(r.runup_radius) +
                                " m leaves the start mark outside the run-up (it is " +
                                std::to_string(start_distance) +
                                " m from the bar's centre); set runup_radius to at least that");
  const double first = s.at("bar_height"), raise = s.at("bar_raise");
  const int count = raise > 0 ? static_cast<int>(s.at("heights")) : 1;
  r.heights.clear();
  for (int i = 0; i < count; ++i) r.heights.push_back(first + i * raise);
  r.tries_per_height = s.at("tries");
  // TR 26.9 lowers and raises by 2 cm; here by the competition's own raise, so that a jump-off
  // bar is a height of the competition's ladder
  r.jump_off_step = r.official && raise > 0 ? raise : 0.0;
  r.attempt_s = s.at("attempt_s");
  return r;
}

std::unique_ptr<SportMatch> HighJumpSport::create(const MatchSettings& settings) const {
  MatchSettings s = settings;
  const HighJumpRules r = rules(s.options);
  if (s.time_limit_s <= 0) {  // every try at every height, and room for a short jump-off
    s.time_limit_s = r.attempt_s * r.tries_per_height * static_cast<double>(r.heights.size());
    if (r.jump_off_step > 0 && modes_.at(s.mode).slot_count() > 1)
      s.time_limit_s += 4 * r.attempt_s;
  }
  return std::make_unique<HighJumpMatch>(r, modes_.at(s.mode), layout(s.mode), s);
}

Layout HighJumpSport::layout(const std::string& mode) const {
  modes_.at(mode);
  return smpl_layout(high_jump_task_layout(), high_jump_rewards(), high_jump_calls());
}

}  // namespace olympics::sports::high_jump

namespace olympics::sports {
std::unique_ptr<Sport> make_high_jump() { return std::make_unique<high_jump::HighJumpSport>(); }
}  // namespace olympics::sports
