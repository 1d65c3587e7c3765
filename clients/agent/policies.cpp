#include "policies.h"

#include <algorithm>
#include <stdexcept>

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

}  // namespace

std::vector<std::string> policy_names() { return {"zero", "random"}; }

std::unique_ptr<Policy> make_policy(const std::string& name, std::uint64_t seed) {
  if (name == "zero") return std::make_unique<ZeroPolicy>();
  if (name == "random") return std::make_unique<RandomPolicy>(seed);
  std::string known;
  for (const auto& n : policy_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown policy \"" + name + "\"; known policies: " + known);
}

}  // namespace olympics::client
