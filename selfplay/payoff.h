// The decayed payoff matrix between entrants and AlphaStar's prioritized fictitious self-play
// (PFSP) opponent sampling over it.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace olympics::selfplay {

// Win/draw/loss counts per ordered pair, each decayed by `decay` whenever that pair plays again
// (AlphaStar: 0.99), so old results fade. win_rate(a, b) counts a draw as half a win.
class PayoffMatrix {
 public:
  explicit PayoffMatrix(int entrants = 0, double decay = 0.99);
  void add_entrant();
  int size() const { return n_; }
  // score_a: 1 = a won, 0.5 = draw, 0 = a lost.
  void record(int a, int b, double score_a);
  double win_rate(int a, int b) const;  // 0.5 when they never met
  double games(int a, int b) const;     // decayed count

 private:
  int n_;
  double decay_;
  std::vector<double> wins_, draws_, games_;  // n x n, row = first entrant
};

enum class PfspWeighting {
  Hard,      // (1 - x)^2: the opponents we lose to
  Variance,  // x (1 - x): the opponents at our level
  Linear,    // 1 - x
  Even,      // 1: uniform
  Capped,    // min(0.5, 1 - x): AlphaStar's, for opponents a main agent already beats
};

PfspWeighting parse_weighting(const std::string& name);  // throws on unknown names
double pfsp_weight(PfspWeighting w, double win_rate);

// Probabilities of picking each candidate as `player`'s opponent (candidates' weights from the
// player's win rate against them, normalised; uniform when every weight is zero).
std::vector<double> pfsp_probabilities(const PayoffMatrix& payoff, int player,
                                       const std::vector<int>& candidates, PfspWeighting w);
int pfsp_sample(const PayoffMatrix& payoff, int player, const std::vector<int>& candidates,
                PfspWeighting w, std::mt19937_64& rng);

}  // namespace olympics::selfplay
