// Golf as a sport: modes, settings (the seed's task or the Rules of Golf), the layout.
#pragma once

#include "golf/golf_rules.h"
#include "sport.h"

namespace olympics::sports::golf {

class GolfSport : public Sport {
 public:
  GolfSport();
  std::string name() const override { return "golf"; }
  std::string summary() const override {
    return "golf: a club held in the hand, a ball on a green, a 108 mm hole; the fewest strokes "
           "win";
  }
  const ModeTable& modes() const override { return modes_; }
  double default_time_limit_s() const override { return 10.0; }
  std::unique_ptr<SportMatch> create(const MatchSettings& settings) const override;
  Layout layout(const std::string& mode) const override;
  std::vector<SettingSpec> settings() const override;
  GolfRules rules(const nlohmann::json& options) const;

 private:
  ModeTable modes_;
};

}  // namespace olympics::sports::golf
