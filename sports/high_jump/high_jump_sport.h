// The high jump as a sport: modes, settings (the seed's or World Athletics'), the layout.
#pragma once

#include "high_jump/high_jump_rules.h"
#include "sport.h"

namespace olympics::sports::high_jump {

class HighJumpSport : public Sport {
 public:
  HighJumpSport();
  std::string name() const override { return "high_jump"; }
  std::string summary() const override {
    return "high jump: a run-up and a leap over a crossbar that falls when knocked";
  }
  const ModeTable& modes() const override { return modes_; }
  double default_time_limit_s() const override { return 20.0; }
  std::unique_ptr<SportMatch> create(const MatchSettings& settings) const override;
  Layout layout(const std::string& mode) const override;
  std::vector<SettingSpec> settings() const override;
  HighJumpRules rules(const nlohmann::json& options) const;

 private:
  ModeTable modes_;
};

}  // namespace olympics::sports::high_jump
