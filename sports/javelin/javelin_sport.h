// The javelin throw as a sport: modes, settings (the seed's or World Athletics'), the layout.
#pragma once

#include "javelin/javelin_rules.h"
#include "sport.h"

namespace olympics::sports::javelin {

class JavelinSport : public Sport {
 public:
  JavelinSport();
  std::string name() const override { return "javelin"; }
  std::string summary() const override {
    return "javelin throw (SMPL-X, fingers): the javelin held at the cord, thrown from behind "
           "the arc, tip first into the sector";
  }
  const ModeTable& modes() const override { return modes_; }
  double default_time_limit_s() const override { return 10.0; }
  std::unique_ptr<SportMatch> create(const MatchSettings& settings) const override;
  Layout layout(const std::string& mode) const override;
  std::vector<SettingSpec> settings() const override;
  JavelinRules rules(const nlohmann::json& options) const;

 private:
  ModeTable modes_;
};

}  // namespace olympics::sports::javelin
