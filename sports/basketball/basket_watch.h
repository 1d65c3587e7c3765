// Follows the ball through the rims, physics step by physics step, and says what the rules make
// of each passage (FIBA Official Basketball Rules, art. 16: a goal is a live ball entering the
// basket from above; the ball passing up through the basket from below is a violation):
//
// - up through a rim inside it: "from below" (a violation; no basket, ever, for that passage);
// - down through a rim inside it: a basket, unless the ball had come up through that rim and not
//   yet gone back down through its plane (the same ball falling back is no basket).
//
// Any downward passage through the rims' height ends "came up through": the ball is below the
// rim again, and a later shot from above counts. A player's touch ends it too (a new shot).
#pragma once

#include <Eigen/Core>
#include <array>

#include "basketball/court.h"

namespace olympics::sports::basketball {

struct RimPassage {
  int basket = -1;      // down through this rim from above: a basket
  int from_below = -1;  // up through this rim from below: a violation
};

class BasketWatch {
 public:
  explicit BasketWatch(const Court& court) : court_(court) {}

  // The ball's centre moved from `before` to `after` in one physics step.
  RimPassage step(const Eigen::Vector3d& before, const Eigen::Vector3d& after);
  // A player touched the ball, or play restarted: whatever came before is forgotten.
  void reset() { came_up_.fill(false); }

 private:
  Court court_;
  std::array<bool, 2> came_up_{};  // per basket: up through it, not yet back down its plane
};

}  // namespace olympics::sports::basketball
