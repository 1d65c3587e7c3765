#include "javelin/javelin_sport.h"

#include "athletics/competition.h"
#include "javelin/javelin_match.h"
#include "javelin/javelin_rewards.h"

namespace olympics::sports::javelin {

JavelinSport::JavelinSport()
    : modes_(athletics::field_event_modes("javelin", "a series of javelin throws")) {}

std::vector<SettingSpec> JavelinSport::settings() const {
  // Official: World Athletics Technical Rules 25 (field events), 32 (throws: the runway, the
  // arc, the sector, the measurement) and 39 (the javelin: the implement, the valid throw).
  return {
      SettingSpec::rules_preset(),
      SettingSpec::choice("measure", "paper",
                          "the seed's: stages by ticks, ended by dropping the javelin, its "
                          "attitude straying, or it still near the hand in flight; the mark is "
                          "its x where it drops below 0.3 m; or \"official\": tip first inside "
                          "the 28.96 degree sector, no touching the arc, measured from the arc",
                          {"paper", "official"})
          .with_official("official"),
      SettingSpec::choice("implement", "paper",
                          "SMPLOlympics' javelin (2.45 kg, 2.70 m, centre of mass 1.45 m from "
                          "the tip) or the men's official one (800 g, 2.65 m, centre of mass and "
                          "cord 1.00 m from the tip)",
                          {"paper", "official"})
          .with_official("official"),
      SettingSpec::choice("aerodynamics", "none",
                          "none (the seed's simulator has no air) or crossflow: lift, drag and "
                          "the pitching moment of a slender body (docs/athletics.md)",
                          {"none", "crossflow"})
          .with_official("crossflow"),
      SettingSpec::number("run_up", 2.0,
                          "m from the start mark to the arc's inner edge (a standing throw: 2; "
                          "TR 32.9: a runway of at least 30 m)",
                          1, 36.5)
          .with_official(30.0),
      SettingSpec::number("attempts", 1,
                          "attempts per athlete (the seed's episode: 1; TR 25.5: 3 rounds)", 1, 6)
          .with_official(3),
      SettingSpec::number("attempt_s", 10.0, "s an attempt may last (TR 25.17: 1 minute)", 2, 60)
          .with_official(60.0),
      SettingSpec::number("present_s", 0.5,
                          "s the grip holds the javelin whatever the fingers do at the start of "
                          "an attempt, so that they can close on the cord",
                          0, 2),
  };
}

JavelinRules JavelinSport::rules(const nlohmann::json& options) const {
  const nlohmann::json s = merge_settings(name(), settings(), options);
  JavelinRules r;
  r.official = s.at("measure") == "official";
  r.javelin = s.at("implement") == "official" ? official_javelin() : paper_javelin();
  r.aerodynamics = s.at("aerodynamics") == "crossflow";
  r.run_up = s.at("run_up");
  r.attempts = s.at("attempts");
  r.attempt_s = s.at("attempt_s");
  r.present_s = s.at("present_s");
  return r;
}

std::unique_ptr<SportMatch> JavelinSport::create(const MatchSettings& settings) const {
  MatchSettings s = settings;
  const JavelinRules r = rules(s.options);
  if (s.time_limit_s <= 0) s.time_limit_s = r.attempts * r.attempt_s;
  return std::make_unique<JavelinMatch>(r, modes_.at(s.mode), layout(s.mode), s);
}

Layout JavelinSport::layout(const std::string& mode) const {
  modes_.at(mode);
  return humanoid_layout(kHumanoid, javelin_task_layout(), javelin_rewards(), javelin_calls());
}

}  // namespace olympics::sports::javelin

namespace olympics::sports {
std::unique_ptr<Sport> make_javelin() { return std::make_unique<javelin::JavelinSport>(); }
}  // namespace olympics::sports
