#include "payoff.h"

#include <algorithm>
#include <stdexcept>
#include <tuple>

namespace olympics::selfplay {

PayoffMatrix::PayoffMatrix(int entrants, double decay)
    : n_(entrants), decay_(decay), wins_(n_ * n_), draws_(n_ * n_), games_(n_ * n_) {}

void PayoffMatrix::add_entrant() {
  const int old = n_;
  ++n_;
  auto grow = [&](std::vector<double>& m) {
    std::vector<double> bigger(n_ * n_, 0.0);
    for (int i = 0; i < old; ++i)
      for (int j = 0; j < old; ++j) bigger[i * n_ + j] = m[i * old + j];
    m.swap(bigger);
  };
  grow(wins_), grow(draws_), grow(games_);
}

void PayoffMatrix::record(int a, int b, double score_a) {
  if (a < 0 || b < 0 || a >= n_ || b >= n_ || a == b)
    throw std::invalid_argument("PayoffMatrix::record: bad pair");
  for (auto [x, y, s] : {std::tuple{a, b, score_a}, std::tuple{b, a, 1.0 - score_a}}) {
    const int k = x * n_ + y;
    wins_[k] = wins_[k] * decay_ + (s == 1.0 ? 1.0 : 0.0);
    draws_[k] = draws_[k] * decay_ + (s == 0.5 ? 1.0 : 0.0);
    games_[k] = games_[k] * decay_ + 1.0;
  }
}

double PayoffMatrix::win_rate(int a, int b) const {
  const int k = a * n_ + b;
  if (games_[k] <= 0) return 0.5;
  return (wins_[k] + 0.5 * draws_[k]) / games_[k];
}

double PayoffMatrix::games(int a, int b) const { return games_[a * n_ + b]; }

PfspWeighting parse_weighting(const std::string& name) {
  if (name == "hard") return PfspWeighting::Hard;
  if (name == "variance") return PfspWeighting::Variance;
  if (name == "linear") return PfspWeighting::Linear;
  if (name == "even") return PfspWeighting::Even;
  if (name == "capped") return PfspWeighting::Capped;
  throw std::invalid_argument("unknown PFSP weighting \"" + name +
                              "\"; known: hard, variance, linear, even, capped");
}

double pfsp_weight(PfspWeighting w, double x) {
  switch (w) {
    case PfspWeighting::Hard:
      return (1 - x) * (1 - x);
    case PfspWeighting::Variance:
      return x * (1 - x);
    case PfspWeighting::Linear:
      return 1 - x;
    case PfspWeighting::Even:
      return 1;
    case PfspWeighting::Capped:
      return std::min(0.5, 1 - x);
  }
  return 1;
}

std::vector<double> pfsp_probabilities(const PayoffMatrix& payoff, int player,
                                       const std::vector<int>& candidates, PfspWeighting w) {
  std::vector<double> p;
  double total = 0;
  for (int c : candidates) {
    p.push_back(pfsp_weight(w, payoff.win_rate(player, c)));
    total += p.back();
  }
  for (auto& x : p) x = total > 0 ? x / total : 1.0 / static_cast<double>(candidates.size());
  return p;
}

int pfsp_sample(const PayoffMatrix& payoff, int player, const std::vector<int>& candidates,
                PfspWeighting w, std::mt19937_64& rng) {
  if (candidates.empty()) throw std::invalid_argument("pfsp_sample: no candidates");
  auto p = pfsp_probabilities(payoff, player, candidates, w);
  // Inverse-CDF sampling with a uniform draw made from the raw 64 bits: the standard
  // distributions' algorithms are each library's choice, and a league must pick the same
  // opponents on every platform.
  double u = static_cast<double>(rng() >> 11) * 0x1.0p-53, acc = 0;
  for (size_t i = 0; i < p.size(); ++i)
    if ((acc += p[i]) > u) return candidates[i];
  return candidates.back();
}

}  // namespace olympics::selfplay
