#include "policies.h"

#include <algorithm>
#include <stdexcept>

#include "mlp_snapshot.h"
#include "scripted_policy.h"

namespace olympics::client {
namespace {

class ZeroPolicy : public Policy {
 public:
  void act(std::span<const float>, std::span<float> action) override {
    std::fill(action.begin(), action.end(), 0.0f);
  }
};

class RandomPolicy : public Policy {
 public:
  explicit RandomPolicy(std::uint64_t seed) : rng_(seed) {}
  void act(std::span<const float>, std::span<float> action) override {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (auto& a : action) a = u(rng_);
  }

 private:
  std::mt19937_64 rng_;
};

// A snapshot's MLP; with metadata residual = "scripted" (a residual policy, docs/training.md)
// the action is the scripted baseline's plus the MLP's clipped to [-1, 1], as in training (the
// baseline's own targets may lie beyond +-1 and are kept).
class SnapshotPolicy : public Policy {
 public:
  explicit SnapshotPolicy(const std::string& path) : snapshot_(MlpSnapshot::load(path)) {
    const auto it = snapshot_.metadata().find("residual");
    const std::string residual = it == snapshot_.metadata().end() ? "" : it->second;
    if (residual == "scripted")
      base_ = std::make_unique<ScriptedPolicy>();
    else if (!residual.empty() && residual != "none")
      throw std::invalid_argument(path + ": residual \"" + residual +
                                  "\" is not a base policy this player knows (scripted, none)");
  }
  void start(const MatchInfo& match) override {
    if (base_) base_->start(match);
  }
  void act(std::span<const float> observation, std::span<float> action) override {
    snapshot_.act(observation, action);
    if (!base_) return;
    base_action_.resize(action.size());
    base_->act(observation, base_action_);
    for (size_t i = 0; i < action.size(); ++i)
      action[i] = std::clamp(action[i], -1.0f, 1.0f) + base_action_[i];
  }

 private:
  MlpSnapshot snapshot_;
  std::unique_ptr<Policy> base_;
  std::vector<float> base_action_;
};

}  // namespace

std::vector<std::string> policy_names() {
  return {"zero", "random", "scripted", "mlp:<snapshot.safetensors>"};
}

std::unique_ptr<Policy> make_policy(const std::string& name, std::uint64_t seed) {
  if (name == "zero") return std::make_unique<ZeroPolicy>();
  if (name == "random") return std::make_unique<RandomPolicy>(seed);
  if (name == "scripted") return std::make_unique<ScriptedPolicy>();
  if (name.rfind("mlp:", 0) == 0) return std::make_unique<SnapshotPolicy>(name.substr(4));
  std::string known;
  for (const auto& n : policy_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown policy \"" + name + "\"; known policies: " + known);
}

}  // namespace olympics::client
