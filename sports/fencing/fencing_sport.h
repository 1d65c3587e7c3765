// Fencing (épée, 1v1) as a sport of the registry; docs/combat-sports.md has the rules, settings,
// rewards and observation.
#pragma once

#include "fencing/fencing_match.h"
#include "sport.h"

namespace olympics::sports::fencing {

class FencingSport : public Sport {
 public:
  FencingSport();
  std::string name() const override { return "fencing"; }
  std::string summary() const override {
    return "épée on a 14 x 2 m piste; touches by the tip's contact force, doubles, bout to 5";
  }
  const ModeTable& modes() const override { return modes_; }
  double default_time_limit_s() const override { return 180; }  // the bout's 3 minutes
  std::unique_ptr<SportMatch> create(const MatchSettings& settings) const override;
  Layout layout(const std::string& mode) const override;
  std::vector<SettingSpec> settings() const override;

  // The bout's configuration from a request's options (throws std::invalid_argument).
  FencingConfig config(const nlohmann::json& options) const;

 private:
  ModeTable modes_;
};

}  // namespace olympics::sports::fencing
