// The ball's path as a player predicts it: the server's own flight model (sports/equipment,
// gravity, quadratic drag, bounces off the court or table and the net with their restitution and
// friction), stepped at the server's physics step from the state the observation shows.
//
// Frame: the court seen from the player's side ("court frame": own half at negative x, the net
// along y at x = 0, z up from the ground), as the racket observation's court_position and
// court_heading blocks give it. Both halves are alike, so one arena serves both teams.
#pragma once

#include <Eigen/Geometry>
#include <span>
#include <vector>

#include "racket/racket_game.h"

namespace olympics::client::control {

// Turns the heading-frame vectors of an observation into the court frame.
struct CourtFrame {
  Eigen::Vector3d root = Eigen::Vector3d::Zero();  // the root in the court frame
  double yaw = 0;                                  // heading relative to facing the net, radians
  Eigen::Vector3d point(const Eigen::Vector3d& heading_point) const;
  Eigen::Vector3d vector(const Eigen::Vector3d& heading_vector) const;
  Eigen::Vector3d to_heading_point(const Eigen::Vector3d& court_point) const;
  Eigen::Vector3d to_heading_vector(const Eigen::Vector3d& court_vector) const;
};

struct BallSample {
  double time = 0;  // seconds from now
  Eigen::Vector3d position, velocity;
  int own_bounces = 0;    // bounces on the playing surface of the own half so far
  int other_bounces = 0;  // anywhere else (the far half, the floor beyond the table)
};

class BallPath {
 public:
  explicit BallPath(const sports::racket::RacketGame& game);
  // Steps the ball from its state now (court frame) over `horizon_s` seconds; one sample per
  // physics step, the first one step ahead. `own_bounces` it has made already (the rally flags).
  std::vector<BallSample> predict(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                                  double horizon_s, int own_bounces = 0) const;
  // Where a ball sent from `position` at `velocity` (court frame) first comes down to the
  // playing surface, and its height as it passes over the net (x = 0); no surfaces but the
  // playing height, so this is the "free flight" of a stroke's aim.
  struct Flight {
    Eigen::Vector2d landing{0, 0};
    double net_clearance = -1;  // ball bottom above the net's top where it crosses x = 0
    double seconds = 0;
    bool lands = false;
  };
  Flight fly(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity) const;

  const sports::racket::RacketGame& game() const { return game_; }
  static constexpr double kStep_s = 1.0 / 120;  // the server's physics step

 private:
  sports::racket::RacketGame game_;
  std::vector<sports::equipment::ArenaBox> arena_;
};

}  // namespace olympics::client::control
