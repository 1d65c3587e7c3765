// Soccer as a sport of the registry: modes penalty_kick, penalty_kick_keeper, 1v1, 2v2;
// docs/soccer.md has the field, rules, settings, rewards and observation.
#pragma once

#include "soccer/soccer_match.h"
#include "sport.h"

namespace olympics::sports::soccer {

class SoccerSport : public Sport {
 public:
  SoccerSport();
  std::string name() const override { return "soccer"; }
  std::string summary() const override {
    return "32 x 20 m field, 4 x 2 m goals, a size-5 ball; goals, throw-ins, goal kicks, corners, "
           "kick-offs and halves";
  }
  const ModeTable& modes() const override { return modes_; }
  double default_time_limit_s() const override { return 240; }  // two halves of 120 s
  std::unique_ptr<SportMatch> create(const MatchSettings& settings) const override;
  Layout layout(const std::string& mode) const override;
  std::vector<SettingSpec> settings() const override;

  // The match's configuration from a request's options (throws std::invalid_argument).
  SoccerConfig config(const nlohmann::json& options) const;

  static constexpr double kPenaltyKickS = 30;  // a penalty kick's default time limit

 private:
  ModeTable modes_;
};

}  // namespace olympics::sports::soccer
