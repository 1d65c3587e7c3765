#include "scripted_policy.h"

#include <stdexcept>

namespace olympics::client {

// The registry: one line per sport with a scripted baseline, naming the factory its file defines
// (std::unique_ptr<Policy> make_scripted_<baseline>() in namespace olympics::client, in
// clients/agent/scripted_<baseline>.cpp, which the client build picks up by its name). Sports
// that play alike share a baseline (tennis and table tennis: racket). Every line ends in a
// backslash, so a new baseline is one added line.
// clang-format off
#define OLYMPICS_SCRIPTED_BASELINES(X) \
  X(tennis, racket)                    \
  X(table_tennis, racket)              \
  X(fencing, fencing)                  \
  X(boxing, boxing)                    \
  X(soccer, soccer)                    \
  X(basketball, basketball_team)       \
  X(javelin, javelin)                  \
  X(hurdles, hurdles)                  \
  X(golf, golf)                        \
  X(long_jump, long_jump)              \
  X(high_jump, high_jump)              \
  /* the list's end */
// clang-format on

#define OLYMPICS_DECLARE_BASELINE(sport, baseline) \
  std::unique_ptr<Policy> make_scripted_##baseline();
OLYMPICS_SCRIPTED_BASELINES(OLYMPICS_DECLARE_BASELINE)
#undef OLYMPICS_DECLARE_BASELINE

namespace {

struct Baseline {
  const char* sport;
  std::unique_ptr<Policy> (*make)();
};

constexpr Baseline kBaselines[] = {
#define OLYMPICS_BASELINE_ENTRY(sport, baseline) {#sport, &make_scripted_##baseline},
    OLYMPICS_SCRIPTED_BASELINES(OLYMPICS_BASELINE_ENTRY)
#undef OLYMPICS_BASELINE_ENTRY
};

}  // namespace

std::vector<std::string> ScriptedPolicy::sports() {
  std::vector<std::string> names;
  for (const auto& b : kBaselines) names.push_back(b.sport);
  return names;
}

void ScriptedPolicy::start(const MatchInfo& match) {
  sport_policy_.reset();
  for (const auto& b : kBaselines)
    if (match.sport == b.sport) sport_policy_ = b.make();
  if (!sport_policy_) {
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
