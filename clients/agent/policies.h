// Policies olympics-agent can play: zero (hold the default pose), random, a frozen MLP snapshot
// (mlp:FILE, docs/snapshots.md), and the scripted baseline of the match's sport.
#pragma once

#include <memory>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "match_info.h"

namespace olympics::client {

class Policy {
 public:
  virtual ~Policy() = default;
  // Called once before a match's first act(), for every match the policy plays; throws
  // std::invalid_argument when it cannot play that match (e.g. a scripted sport it does not know).
  virtual void start(const MatchInfo& match) { (void)match; }
  // One action for one slot from that slot's observation.
  virtual void act(std::span<const float> observation, std::span<float> action) = 0;
};

// Throws std::invalid_argument listing the known policies when `name` is unknown.
std::unique_ptr<Policy> make_policy(const std::string& name, std::uint64_t seed);
std::vector<std::string> policy_names();

}  // namespace olympics::client
