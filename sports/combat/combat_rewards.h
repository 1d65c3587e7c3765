// The rewards of fencing and boxing (SPORTS.md; the seed's eq. 9-10, after NCP's boxing), every
// term by name so that a trainer can re-weight them:
//
//   facing   = exp(-2 (1 - d_x))           d: unit direction (xy) to the opponent's root, in my
//                                           heading frame; 1 when facing it squarely
//   velocity = exp(-4 max(0, 1 - s)^2)     s = my root's xy velocity along d (m/s), if s > 0;
//              0 otherwise                  (1 at 1 m/s or faster towards the opponent)
//   strike   = exp(-10 min_k |p_striker - p_target_k|^2)   over my strikers (the sword's tip, or
//                                           each glove) and the opponent's target bodies
//   point    = 1 on the tick I score (a touch, a scoring punch)
//
//   R = 0.1 facing + 0.1 velocity + 0.6 strike + 1.0 point
//
// The original measures velocity by the root's displacement over a tick; here it is the root's
// velocity at the tick's end, which the same humanoid state gives without history.
#pragma once

#include <Eigen/Core>
#include <array>
#include <span>
#include <string>
#include <vector>

#include "core/humanoid.h"
#include "sport.h"

namespace olympics::sports::combat {

inline constexpr int kCombatTerms = 4;
enum CombatTerm { kFacing = 0, kVelocity = 1, kStrike = 2, kPoint = 3 };

struct CombatRewardInput {
  core::BodyState root;                   // mine
  Eigen::Vector3d opponent_root;          // position
  std::vector<Eigen::Vector3d> strikers;  // world points: my sword's tip, or my gloves
  std::vector<Eigen::Vector3d> targets;   // world points: the opponent's target bodies
  bool scored = false;
};

std::array<float, kCombatTerms> combat_reward_terms(const CombatRewardInput& in);

// The layout's terms; `striker` names what strikes ("the sword's tip", "the nearer glove").
std::vector<RewardTerm> combat_rewards(const std::string& striker);

}  // namespace olympics::sports::combat
