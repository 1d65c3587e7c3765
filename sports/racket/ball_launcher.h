// Where each ball comes from (SPORTS.md): the ball-return launcher and each point's first ball.
//
// A landing point is drawn uniformly on the receiving half (or the receiving player's side of it
// in doubles) and a horizontal speed from the sport's range; the launch is then aimed, with drag,
// by bisection on the vertical speed so that the ball lands on that point, and rejected (and
// drawn again) when it would not clear the net.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <random>

#include "racket/racket_game.h"

namespace olympics::sports::racket {

struct Launch {
  Eigen::Vector3d position, velocity;
  Eigen::Vector2d landing;  // the aimed landing point
};

// The velocity from `from` that lands the ball at `target` (on height surface_height) with the
// given horizontal speed; nullopt when no vertical speed in range does, or the ball would not
// clear the net (when it has to cross it).
std::optional<Launch> aim_ball(const RacketGame& game, const Eigen::Vector3d& from,
                               const Eigen::Vector2d& target, double horizontal_speed);

// Ball return: from the far side towards a point on `team`'s half.
Launch ball_return_launch(const RacketGame& game, int team, std::mt19937_64& rng);

// A point's first ball, from the middle of the net towards the receiving team's half; in
// doubles towards the half of the half where `receiver_y_sign` says the receiver stands.
Launch feed_launch(const RacketGame& game, int team, int receiver_y_sign, bool doubles,
                   std::mt19937_64& rng);
// A point's first ball toward the receiving player, as the seed feeds it (straight at the player):
// it lands deep in the half (55-90% of its length from the net), within 15% of the half's
// width of the receiver's line `receiver_y`.
Launch feed_to_player_launch(const RacketGame& game, int team, double receiver_y,
                             std::mt19937_64& rng);

}  // namespace olympics::sports::racket
