// `--policy scripted`: the scripted baseline of the match's sport (the yardstick learned policies
// must beat), chosen when the match starts from the sport's name.
#pragma once

#include <memory>

#include "policies.h"

namespace olympics::client {

class ScriptedPolicy : public Policy {
 public:
  void start(const MatchInfo& match) override;
  void act(std::span<const float> observation, std::span<float> action) override;

  // The sports that have a scripted baseline.
  static std::vector<std::string> sports();

 private:
  std::unique_ptr<Policy> sport_policy_;
};

}  // namespace olympics::client
