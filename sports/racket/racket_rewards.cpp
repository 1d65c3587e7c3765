#include "racket/racket_rewards.h"

#include <cmath>

#include "equipment/landing.h"

namespace olympics::sports::racket {

std::array<float, kRewardTerms> racket_reward_terms(const RewardInput& in) {
  std::array<float, kRewardTerms> t{};
  if (!in.struck) {
    t[kRacketTerm] = static_cast<float>(std::exp(-(in.racket - in.ball).squaredNorm()));
    return t;
  }
  const Eigen::Vector2d land =
      equipment::predict_landing(in.ball, in.ball_velocity, in.landing_height);
  t[kContactTerm] = 1.0f;
  t[kLandingTerm] = static_cast<float>(std::exp(-(land - in.target).squaredNorm()));
  if (in.counts_hits) t[kHitsTerm] = static_cast<float>(in.hits);
  return t;
}

}  // namespace olympics::sports::racket
