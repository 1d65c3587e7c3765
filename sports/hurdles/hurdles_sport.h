// The hurdles as a sport: modes (one athlete, or a race of 2 to 8 in lanes), settings (the
// seed's or World Athletics'), the layout.
#pragma once

#include "hurdles/hurdles_rules.h"
#include "sport.h"

namespace olympics::sports::hurdles {

class HurdlesSport : public Sport {
 public:
  HurdlesSport();
  std::string name() const override { return "hurdles"; }
  std::string summary() const override {
    return "hurdles: a 110 m (or 100 m) race over ten hurdles, in lanes";
  }
  const ModeTable& modes() const override { return modes_; }
  double default_time_limit_s() const override { return 180.0; }
  std::unique_ptr<SportMatch> create(const MatchSettings& settings) const override;
  Layout layout(const std::string& mode) const override;
  std::vector<SettingSpec> settings() const override;
  HurdlesRules rules(const nlohmann::json& options) const;

 private:
  ModeTable modes_;
};

}  // namespace olympics::sports::hurdles
