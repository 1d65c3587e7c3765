#include "hurdles/hurdles_sport.h"

#include "athletics/competition.h"
#include "hurdles/hurdles_match.h"
#include "hurdles/hurdles_rewards.h"

namespace olympics::sports::hurdles {

HurdlesSport::HurdlesSport()
    : modes_(athletics::field_event_modes("hurdles", "a hurdles race, each in its own lane")) {}

std::vector<SettingSpec> HurdlesSport::settings() const {
  // Official: World Athletics Technical Rules 16-19 (start, lanes, finish, timing) and 22
  // (hurdles).
  return {
      SettingSpec::rules_preset(),
      SettingSpec::choice(
          "judging", "paper",
          "the seed's: the root past the line finishes, a fall, a non-foot touch of "
          "a hurdle over 50 N or the root 0.8 m off the lane's centre end the run; "
          "or \"official\": the torso at the line finishes, leaving the lane or a "
          "trail leg beside a hurdle disqualifies, knocking hurdles over is legal",
          {"paper", "official"})
          .with_official("official"),
      SettingSpec::choice("hurdle", "wall",
                          "the seed's fixed walls (0.05 x 2 x 2.134 m, top at the hurdle height) "
                          "or \"official\" hurdles (TR 22.3: free, 10 kg, 1.20 m wide, overturned "
                          "by a push of tip_force at the top bar)",
                          {"wall", "official"})
          .with_official("official"),
      SettingSpec::choice("race", "110m",
                          "110 m, 1.067 m hurdles 13.72 m then 9.14 m apart (the seed's, the "
                          "men's), or \"100m\" (the women's: 0.838 m, 13.00 m, 8.50 m)",
                          {"110m", "100m"}),
      SettingSpec::number("tip_force", 3.8,
                          "kgf at the top bar's centre that overturns an official hurdle "
                          "(TR 22.3: 3.6 to 4)",
                          3.6, 4.0),
      SettingSpec::number("get_up_s", 10.0,
                          "official: s an athlete may stay down before it did not finish", 1.0,
                          60.0),
  };
}

HurdlesRules HurdlesSport::rules(const nlohmann::json& options) const {
  const nlohmann::json s = merge_settings(name(), settings(), options);
  HurdlesRules r;
  r.official = s.at("judging") == "official";
  r.free_hurdles = s.at("hurdle") == "official";
  if (s.at("race") == "100m") {
    r.race_m = 100.0, r.first_m = 13.00, r.spacing_m = 8.50, r.hurdle_height = 0.838;
  }
  r.tip_force_kgf = s.at("tip_force");
  // Lanes side by side: the official 1.22 m; the seed's 2 m walls need its 2 m.
  r.lane_spacing = r.free_hurdles ? 1.22 : 2.0;
  r.lane_width = r.official ? 1.22 : 2 * r.track_half_width;
  r.start_x = r.official ? -0.3 : 0.0;
  r.get_up_s = s.at("get_up_s");
  return r;
}

std::unique_ptr<SportMatch> HurdlesSport::create(const MatchSettings& settings) const {
  MatchSettings s = settings;
  if (s.time_limit_s <= 0) s.time_limit_s = default_time_limit_s();
  return std::make_unique<HurdlesMatch>(rules(s.options), modes_.at(s.mode), layout(s.mode), s);
}

Layout HurdlesSport::layout(const std::string& mode) const {
  modes_.at(mode);
  return smpl_layout(hurdles_task_layout(), hurdles_rewards(), hurdles_calls());
}

}  // namespace olympics::sports::hurdles

namespace olympics::sports {
std::unique_ptr<Sport> make_hurdles() { return std::make_unique<hurdles::HurdlesSport>(); }
}  // namespace olympics::sports
