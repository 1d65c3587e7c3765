// Boxing (1v1) as a sport of the registry; docs/combat-sports.md has the rules, settings,
// rewards and observation.
#pragma once

#include "boxing/boxing_match.h"
#include "sport.h"

namespace olympics::sports::boxing {

class BoxingSport : public Sport {
 public:
  BoxingSport();
  std::string name() const override { return "boxing"; }
  std::string summary() const override {
    return "gloves in a roped ring; scoring punches by contact force, knock-downs, rounds, cards";
  }
  const ModeTable& modes() const override { return modes_; }
  // The default settings' bout: 3 rounds of 60 s, 10 s rests, 5 s to spare. With other
  // settings, a request's time limit of 0 is the bout's own length.
  double default_time_limit_s() const override { return bout_length_s({}); }
  std::unique_ptr<SportMatch> create(const MatchSettings& settings) const override;
  Layout layout(const std::string& mode) const override;
  std::vector<SettingSpec> settings() const override;

  BoxingConfig config(const nlohmann::json& options) const;

 private:
  ModeTable modes_;
};

}  // namespace olympics::sports::boxing
