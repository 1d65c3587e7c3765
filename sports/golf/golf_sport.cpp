#include "golf/golf_sport.h"

#include "athletics/competition.h"
#include "golf/golf_match.h"
#include "golf/golf_rewards.h"

namespace olympics::sports::golf {

GolfSport::GolfSport()
    : modes_(athletics::field_event_modes("golf", "a hole of golf on its own green")) {}

std::vector<SettingSpec> GolfSport::settings() const {
  // Official: the Rules of Golf (R&A/USGA 2023): Definitions ("hole"), Rules 10.1, 18.2, 21.2;
  // the Equipment Rules for the ball and clubs.
  return {
      SettingSpec::rules_preset(),
      SettingSpec::choice("play", "paper",
                          "the seed's task: one shot at a target 0-20 m to the left, success = "
                          "the ball stops within 1 m; or \"official\": hole out on a green in "
                          "the fewest strokes",
                          {"paper", "official"})
          .with_official("official"),
      SettingSpec::choice("club", "seed_club",
                          "the club held: the seed's (a small head 1.14 m from the hand), a "
                          "putter or a driver",
                          {"seed_club", "putter", "driver"})
          .with_official("putter"),
      SettingSpec::number("distance", 2.0, "m from the ball to the hole (official)", 0.5, 30),
      SettingSpec::number("max_target", 20.0, "m: the seed's target is drawn 0 to this far", 1, 40),
      SettingSpec::number("green_stimp", 3.05,
                          "m a ball rolls on the green from 1.83 m/s (stimp 10 = 3.05 m)", 1, 5),
      SettingSpec::number("green_slope", 0.0,
                          "percent the green falls (official; 0: flat; a ball rolls downhill as "
                          "gravity and rolling resistance say)",
                          0, 10),
      SettingSpec::number("green_fall", 0.0,
                          "degrees: where the green falls, counterclockwise from the line to the "
                          "hole (0: downhill putt, 90: breaks left, 180: uphill)",
                          -180, 360),
      SettingSpec::choice("address", "placed",
                          "official: after a stroke comes to rest the athlete is placed at "
                          "address beside the ball (\"placed\"), or walks to it (\"walk\": "
                          "placed for the first stroke only)",
                          {"placed", "walk"}),
      SettingSpec::number("max_strokes", 6,
                          "Rule 21.2: the maximum score; a hole not finished scores it", 1, 12),
      SettingSpec::number("hole_s", 60.0, "s an athlete has to hole out", 5, 300),
  };
}

GolfRules GolfSport::rules(const nlohmann::json& options) const {
  const nlohmann::json s = merge_settings(name(), settings(), options);
  GolfRules r;
  r.official = s.at("play") == "official";
  const std::string club = s.at("club");
  r.club = club == "putter" ? putter() : club == "driver" ? driver() : seed_club();
  r.distance = s.at("distance");
  r.max_target = s.at("max_target");
  r.green_stimp = s.at("green_stimp");
  r.green_slope = s.at("green_slope");
  r.green_fall_deg = s.at("green_fall");
  r.placed_at_address = s.at("address") == "placed";
  r.max_strokes = s.at("max_strokes");
  r.hole_s = s.at("hole_s");
  return r;
}

std::unique_ptr<SportMatch> GolfSport::create(const MatchSettings& settings) const {
  MatchSettings s = settings;
  const GolfRules r = rules(s.options);
  if (s.time_limit_s <= 0) s.time_limit_s = r.official ? r.hole_s + 1 : default_time_limit_s();
  return std::make_unique<GolfMatch>(r, modes_.at(s.mode), layout(s.mode), s);
}

Layout GolfSport::layout(const std::string& mode) const {
  modes_.at(mode);
  return smpl_layout(golf_task_layout(), golf_rewards(), golf_calls());
}

}  // namespace olympics::sports::golf

namespace olympics::sports {
std::unique_ptr<Sport> make_golf() { return std::make_unique<golf::GolfSport>(); }
}  // namespace olympics::sports
