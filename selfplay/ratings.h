// Ratings: Weng-Lin (the Bradley-Terry "full pairing" model that OpenSkill implements) for teams
// of any size and draws, and Elo for 1v1 reports.
#pragma once

#include <vector>

namespace olympics::selfplay {

struct SkillRating {
  double mu = 25.0;
  double sigma = 25.0 / 3.0;
  // A conservative single number for tables: mu - 3 sigma.
  double ordinal() const { return mu - 3.0 * sigma; }
};

struct WengLinSettings {
  double beta = 25.0 / 6.0;  // performance spread; OpenSkill's default sigma / 2
  double kappa = 1e-4;       // floor of the variance shrink factor
};

// Updates every player's rating after one match. teams[i] lists team i's players; rank[i] is team
// i's place (lower is better, equal ranks draw): any number of teams, so a ranked result of N
// athletes (N teams of one, rank = places) is rated by the same update as a two-team game. Weng &
// Lin (2011), Algorithm 1 with the Bradley-Terry full-pairing model and gamma = sigma_i / c_iq, as
// OpenSkill does.
std::vector<std::vector<SkillRating>> rate_match(const std::vector<std::vector<SkillRating>>& teams,
                                                 const std::vector<int>& rank,
                                                 const WengLinSettings& settings = {});

// Elo after one 1v1 game: score_a is 1 (a won), 0.5 (draw) or 0 (a lost).
struct EloPair {
  double a, b;
};
EloPair elo_update(double rating_a, double rating_b, double score_a, double k = 32.0);

// The score of a against b from their places in one ranked game: 1 when a's place is better
// (lower), 0.5 when equal, 0 when worse.
inline double pair_score(int place_a, int place_b) {
  return place_a < place_b ? 1.0 : place_a == place_b ? 0.5 : 0.0;
}

// Elo after one ranked game of N players (places: 1 = first, equal places tie): every pair is a
// game (the better place wins, equal places draw) rated from the ratings before it, with
// K / (N - 1) so that one player's change stays on the 1v1 scale. For N = 2 it is elo_update.
std::vector<double> elo_ranked(const std::vector<double>& ratings, const std::vector<int>& places,
                               double k = 32.0);

}  // namespace olympics::selfplay
