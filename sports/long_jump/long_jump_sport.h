// The long jump as a sport: modes, settings (the seed's or World Athletics'), the layout.
#pragma once

#include "long_jump/long_jump_rules.h"
#include "sport.h"

namespace olympics::sports::long_jump {

class LongJumpSport : public Sport {
 public:
  LongJumpSport();
  std::string name() const override { return "long_jump"; }
  std::string summary() const override {
    return "long jump: a run-up, a take-off before the foul line, a landing in the sand pit";
  }
  const ModeTable& modes() const override { return modes_; }
  double default_time_limit_s() const override { return 20.0; }
  std::unique_ptr<SportMatch> create(const MatchSettings& settings) const override;
  Layout layout(const std::string& mode) const override;
  std::vector<SettingSpec> settings() const override;
  LongJumpRules rules(const nlohmann::json& options) const;

 private:
  ModeTable modes_;
};

}  // namespace olympics::sports::long_jump
