#include "basketball/basketball_sport.h"

namespace olympics::sports::basketball {

BasketballSport::BasketballSport()
    : modes_("basketball",
             {{"free_throw",
               {0},
               "one shooter behind the free-throw line, the ball presented between its hands"}}) {}

std::vector<SettingSpec> BasketballSport::settings() const {
  return {
      SettingSpec::number("rim_height", 3.05, "m, the rim above the floor (the original's 2.8)",
                          2.0, 3.5),
      SettingSpec::number("free_throw_distance", 4.6, "m from the backboard's plane to the line",
                          1.0, 8.0),
      SettingSpec::number("present_s", 0.5,
                          "s the ball is held still between the shooter's hands at the start", 0,
                          3),
  };
}

BasketballConfig BasketballSport::config(const nlohmann::json& options) const {
  const nlohmann::json s = merge_settings(name(), settings(), options);
  BasketballConfig c;
  c.court.rim_height = s.at("rim_height");
  c.court.free_throw_distance = s.at("free_throw_distance");
  c.present_s = s.at("present_s");
  return c;
}

std::unique_ptr<SportMatch> BasketballSport::create(const MatchSettings& settings) const {
  MatchSettings s = settings;
  const BasketballConfig c = config(s.options);
  if (s.time_limit_s <= 0) s.time_limit_s = default_time_limit_s();
  return std::make_unique<BasketballMatch>(c, modes_.at(s.mode), layout(s.mode), s);
}

Layout BasketballSport::layout(const std::string& mode) const {
  modes_.at(mode);
  return smplx_layout(free_throw_layout(), free_throw_rewards(), basketball_calls());
}

}  // namespace olympics::sports::basketball

namespace olympics::sports {
std::unique_ptr<Sport> make_basketball() { return std::make_unique<basketball::BasketballSport>(); }
}  // namespace olympics::sports
