#include "boxing/boxing_sport.h"

#include <cmath>

#include "combat/combat_rewards.h"

namespace olympics::sports::boxing {

BoxingSport::BoxingSport() : modes_("boxing", {{"1v1", {0, 1}, "a bout between two boxers"}}) {}

std::vector<SettingSpec> BoxingSport::settings() const {
  return {
      SettingSpec::rules_preset(),
      SettingSpec::number("ring_size", 5.0,
                          "m inside the ropes (the seed's 5; AIBA 6.10, professional 4.88-7.32)", 3,
                          8)
          .with_official(6.10),  // AIBA Technical Rules: 6.10 m inside the ropes
      SettingSpec::choice("gloves", "both", "both hands gloved, or the seed's \"right\" only",
                          {"both", "right"}),
      SettingSpec::number("punch_force_n", 100.0,
                          "N: a blow's contact force, in its first physics step, that scores", 1,
                          5000),
      SettingSpec::number("punch_speed", 1.0,
                          "m/s: a glove scores only arriving this fast (towards the body it "
                          "meets, along the contact normal); a glove resting or pushing never "
                          "scores",
                          0, 20),
      SettingSpec::number("knuckle_cone_deg", 60.0,
                          "degrees: a glove scores only landing within this of its knuckle "
                          "face's centre (the face away from the wrist)",
                          0, 180),
      SettingSpec::number("punch_refractory_s", 0.3, "s: one glove scores at most this often", 0.05,
                          2),
      SettingSpec::number("rounds", 3, "rounds in the bout", 1, 12),
      SettingSpec::number("round_s", 60.0, "s a round lasts (real: 180, amateur 120-180)", 5, 300)
          .with_official(180.0),  // AIBA: 3 rounds of 3 minutes
      SettingSpec::number("rest_s", 10.0, "s of rest between rounds (real: 60)", 0, 120)
          .with_official(60.0),  // AIBA: 1 minute between rounds
      SettingSpec::number("count_s", 10.0, "s a knocked-down boxer has to get up", 1, 30),
      SettingSpec::number("mandatory_count_s", 8.0,
                          "s a knocked-down boxer is counted even if up at once (the mandatory "
                          "eight count; 0: none)",
                          0, 30),
  };
}

BoxingConfig BoxingSport::config(const nlohmann::json& options) const {
  const nlohmann::json s = merge_settings(name(), settings(), options);
  BoxingConfig c;
  c.ring.size = s.at("ring_size");
  c.both_gloves = s.at("gloves") == "both";
  c.punch_force_n = s.at("punch_force_n");
  c.punch_refractory_s = s.at("punch_refractory_s");
  c.blows.min_closing_speed = s.at("punch_speed");
  c.blows.knuckle_cone_cos = std::cos(s.at("knuckle_cone_deg").get<double>() * M_PI / 180);
  c.rules.rounds = s.at("rounds");
  c.rules.round_s = s.at("round_s");
  c.rules.rest_s = s.at("rest_s");
  c.rules.count_s = s.at("count_s");
  c.rules.mandatory_count_s = s.at("mandatory_count_s");
  return c;
}

std::unique_ptr<SportMatch> BoxingSport::create(const MatchSettings& settings) const {
  MatchSettings s = settings;
  const BoxingConfig c = config(s.options);
  if (s.time_limit_s <= 0) s.time_limit_s = bout_length_s(c.rules);
  return std::make_unique<BoxingMatch>(c, modes_.at(s.mode), layout(s.mode), s);
}

Layout BoxingSport::layout(const std::string& mode) const {
  modes_.at(mode);
  return smpl_layout(boxing_task_layout(), combat::combat_rewards("each glove"), boxing_calls());
}

}  // namespace olympics::sports::boxing

namespace olympics::sports {
std::unique_ptr<Sport> make_boxing() { return std::make_unique<boxing::BoxingSport>(); }
}  // namespace olympics::sports
