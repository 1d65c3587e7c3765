#include "ratings.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace olympics::selfplay {

std::vector<std::vector<SkillRating>> rate_match(const std::vector<std::vector<SkillRating>>& teams,
                                                 const std::vector<int>& rank,
                                                 const WengLinSettings& s) {
  if (teams.size() != rank.size() || teams.size() < 2)
    throw std::invalid_argument("rate_match needs at least two teams and one rank per team");
  const size_t n = teams.size();
  std::vector<double> team_mu(n, 0), team_var(n, 0);
  for (size_t i = 0; i < n; ++i) {
    if (teams[i].empty()) throw std::invalid_argument("rate_match: a team without players");
    for (const auto& p : teams[i]) team_mu[i] += p.mu, team_var[i] += p.sigma * p.sigma;
  }
  std::vector<std::vector<SkillRating>> out = teams;
  for (size_t i = 0; i < n; ++i) {
    double omega = 0, delta = 0;
    for (size_t q = 0; q < n; ++q) {
      if (q == i) continue;
      const double c = std::sqrt(team_var[i] + team_var[q] + 2 * s.beta * s.beta);
      const double p_iq = 1.0 / (1.0 + std::exp((team_mu[q] - team_mu[i]) / c));
      const double score = rank[q] > rank[i] ? 1.0 : rank[q] == rank[i] ? 0.5 : 0.0;
      omega += team_var[i] / c * (score - p_iq);
      const double gamma = std::sqrt(team_var[i]) / c;
      delta += gamma * team_var[i] / (c * c) * p_iq * (1 - p_iq);
    }
    for (auto& p : out[i]) {
      const double var = p.sigma * p.sigma;
      p.mu += var / team_var[i] * omega;
      p.sigma = std::sqrt(var * std::max(1 - var / team_var[i] * delta, s.kappa));
    }
  }
  return out;
}

EloPair elo_update(double a, double b, double score_a, double k) {
  const double expected_a = 1.0 / (1.0 + std::pow(10.0, (b - a) / 400.0));
  const double change = k * (score_a - expected_a);
  return {a + change, b - change};
}

std::vector<double> elo_ranked(const std::vector<double>& ratings, const std::vector<int>& places,
                               double k) {
  if (ratings.size() != places.size() || ratings.size() < 2)
    throw std::invalid_argument("elo_ranked needs at least two players and one place each");
  const size_t n = ratings.size();
  const double k_pair = k / static_cast<double>(n - 1);
  std::vector<double> change(n, 0.0);
  for (size_t a = 0; a < n; ++a)
    for (size_t b = a + 1; b < n; ++b) {
      const EloPair e =
          elo_update(ratings[a], ratings[b], pair_score(places[a], places[b]), k_pair);
      change[a] += e.a - ratings[a], change[b] += e.b - ratings[b];
    }
  std::vector<double> out(n);
  for (size_t i = 0; i < n; ++i) out[i] = ratings[i] + change[i];
  return out;
}

}  // namespace olympics::selfplay
