#include "scripted_policy.h"

#include <stdexcept>

#include "scripted_basketball.h"
#include "scripted_boxing.h"
#include "scripted_fencing.h"
#include "scripted_racket.h"
#include "scripted_soccer.h"

namespace olympics::client {

std::vector<std::string> ScriptedPolicy::sports() {
  return {"tennis", "table_tennis", "fencing", "boxing", "soccer", "basketball"};
}

void ScriptedPolicy::start(const MatchInfo& match) {
  if (match.sport == "tennis" || match.sport == "table_tennis")
    sport_policy_ = std::make_unique<ScriptedRacketPolicy>();
  else if (match.sport == "fencing")
    sport_policy_ = std::make_unique<ScriptedFencingPolicy>();
  else if (match.sport == "boxing")
    sport_policy_ = std::make_unique<ScriptedBoxingPolicy>();
  else if (match.sport == "soccer")
    sport_policy_ = std::make_unique<ScriptedSoccerPolicy>();
  else if (match.sport == "basketball")
    sport_policy_ = std::make_unique<ScriptedBasketballPolicy>();
  else {
    std::string known;
    for (const auto& s : sports()) known += (known.empty() ? "" : ", ") + s;
    throw std::invalid_argument("no scripted policy plays " + match.sport +
                                "; scripted baselines exist for: " + known);
  }
  sport_policy_->start(match);
}

void ScriptedPolicy::act(std::span<const float> observation, std::span<float> action) {
  if (!sport_policy_) throw std::logic_error("ScriptedPolicy: act() before start()");
  sport_policy_->act(observation, action);
}

}  // namespace olympics::client
