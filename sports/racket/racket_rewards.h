// The rewards of tennis and table tennis (SPORTS.md; the seed's eq. 8 and its table-tennis
// variant), every term by name so that a trainer can re-weight them:
//
//   racket  = exp(-|p_racket - p_ball|^2)               while C = 0 (not yet struck this ball)
//   contact = 1                                          once C = 1
//   landing = exp(-|p_land - p_target|^2)                once C = 1; p_land from eq. 6
//   hits    = N_hits (successful returns this episode)   once C = 1, table tennis only
//
// The reward is their sum, which is the seed's R = r_racket (C = 0) or r_ball (C = 1).
#pragma once

#include <Eigen/Core>
#include <array>

namespace olympics::sports::racket {

inline constexpr int kRewardTerms = 4;
enum RacketRewardTerm { kRacketTerm = 0, kContactTerm = 1, kLandingTerm = 2, kHitsTerm = 3 };

struct RewardInput {
  Eigen::Vector3d racket;  // centre of the racket face
  Eigen::Vector3d ball, ball_velocity;
  Eigen::Vector2d target;  // on the opponent's half
  bool struck = false;     // C: this player has struck the ball coming to it
  int hits = 0;            // successful returns this episode
  bool counts_hits = false;
  double landing_height = 0;
};

std::array<float, kRewardTerms> racket_reward_terms(const RewardInput& in);

}  // namespace olympics::sports::racket
