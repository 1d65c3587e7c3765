// Basketball as a sport of the registry (SMPL-X humanoids with fingers): modes free_throw, 1v1
// and 2v2;
// docs/basketball.md has the court, the ball, holding it, the rules and the rewards.
#pragma once

#include "basketball/basketball_match.h"
#include "sport.h"

namespace olympics::sports::basketball {

class BasketballSport : public Sport {
 public:
  BasketballSport();
  std::string name() const override { return "basketball"; }
  std::string summary() const override {
    return "FIBA 3x3 half court, a rim at 3.05 m as a real ring on a backboard, a size-7 ball "
           "held by the SMPL-X hands' friction; free throws, 1v1 and 2v2 by 3x3 rules";
  }
  const ModeTable& modes() const override { return modes_; }
  // A free throw's; team play's is the game_s setting.
  double default_time_limit_s() const override { return kFreeThrowS; }
  static constexpr double kFreeThrowS = 6;
  std::unique_ptr<SportMatch> create(const MatchSettings& settings) const override;
  Layout layout(const std::string& mode) const override;
  std::vector<SettingSpec> settings() const override;

  // The match's configuration from a request's options (throws std::invalid_argument).
  BasketballConfig config(const nlohmann::json& options) const;

 private:
  ModeTable modes_;
};

}  // namespace olympics::sports::basketball
