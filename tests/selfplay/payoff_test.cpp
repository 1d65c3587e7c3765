#include "payoff.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace olympics::selfplay {
namespace {

TEST(PayoffMatrix, DecaysOldResults) {
  PayoffMatrix m(2, 0.99);
  EXPECT_DOUBLE_EQ(m.win_rate(0, 1), 0.5);  // never met
  m.record(0, 1, 1.0);
  EXPECT_DOUBLE_EQ(m.win_rate(0, 1), 1.0);
  EXPECT_DOUBLE_EQ(m.win_rate(1, 0), 0.0);
  m.record(0, 1, 0.0);
  // wins 0.99, games 1.99: the older win weighs a little less than the newer loss.
  EXPECT_NEAR(m.win_rate(0, 1), 0.99 / 1.99, 1e-15);
  m.record(0, 1, 0.5);
  EXPECT_NEAR(m.win_rate(0, 1), (0.99 * 0.99 + 0.5) / (1.99 * 0.99 + 1), 1e-15);
  m.add_entrant();
  EXPECT_EQ(m.size(), 3);
  EXPECT_NEAR(m.win_rate(0, 1), (0.99 * 0.99 + 0.5) / (1.99 * 0.99 + 1), 1e-15);
  EXPECT_DOUBLE_EQ(m.win_rate(2, 0), 0.5);
}

TEST(Pfsp, WeightingsAreAlphaStars) {
  EXPECT_DOUBLE_EQ(pfsp_weight(PfspWeighting::Hard, 0.25), 0.5625);
  EXPECT_DOUBLE_EQ(pfsp_weight(PfspWeighting::Variance, 0.25), 0.1875);
  EXPECT_DOUBLE_EQ(pfsp_weight(PfspWeighting::Capped, 0.25), 0.5);
  EXPECT_DOUBLE_EQ(pfsp_weight(PfspWeighting::Capped, 0.75), 0.25);
  EXPECT_THROW(parse_weighting("harder"), std::invalid_argument);
}

// Player 0 beats 1 always, 2 half the time, never beats 3. With (1-x)^2 the probabilities are
// 0 : 0.25 : 1 normalised = 0, 0.2, 0.8; sampled 20,000 times with a fixed seed, each frequency is
// within 4 standard deviations of its probability.
TEST(Pfsp, PicksOpponentsWithTheStatedProbabilities) {
  PayoffMatrix m(4, 1.0);
  for (int k = 0; k < 10; ++k) {
    m.record(0, 1, 1.0);
    m.record(0, 2, k % 2 ? 1.0 : 0.0);
    m.record(0, 3, 0.0);
  }
  const std::vector<int> candidates = {1, 2, 3};
  auto p = pfsp_probabilities(m, 0, candidates, PfspWeighting::Hard);
  EXPECT_NEAR(p[0], 0.0, 1e-12);
  EXPECT_NEAR(p[1], 0.2, 1e-12);
  EXPECT_NEAR(p[2], 0.8, 1e-12);
  std::mt19937_64 rng(2026);
  std::map<int, int> counts;
  const int n = 20000;
  for (int i = 0; i < n; ++i) ++counts[pfsp_sample(m, 0, candidates, PfspWeighting::Hard, rng)];
  for (size_t i = 0; i < candidates.size(); ++i) {
    const double sd = std::sqrt(n * p[i] * (1 - p[i]));
    EXPECT_NEAR(counts[candidates[i]], n * p[i], 4 * sd + 1e-9) << "opponent " << candidates[i];
  }
  EXPECT_EQ(counts[1], 0);  // an opponent always beaten is never picked under "hard"
  // Variance weighting prefers the even match-up: x(1-x) = 0, 0.25, 0.
  auto v = pfsp_probabilities(m, 0, candidates, PfspWeighting::Variance);
  EXPECT_NEAR(v[1], 1.0, 1e-12);
}

}  // namespace
}  // namespace olympics::selfplay
