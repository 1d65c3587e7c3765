// A small fast ball flying through an arena, with continuous collision against everything it can
// hit: the ground, static boxes (a table top, a net) and moving discs (rackets, paddles).
//
// Tennis and table-tennis balls are simulated here rather than as ODE bodies: at 70 m/s a ball
// moves 0.58 m per 120 Hz step, more than a net or a racket is thick, and ODE has no continuous
// collision. Each step the ball moves along its (drag and gravity) path and the first contact of
// that segment with any surface is found exactly (analytically for the ground, by conservative
// advancement for boxes and moving discs); the ball bounces there and flies on for the rest of
// the step. The ball is much lighter than anything it hits, so surfaces are not pushed back here:
// the caller applies the reaction on a racket's hand from the reported impulse.
#pragma once

#include <Eigen/Geometry>
#include <span>
#include <vector>

#include "equipment/ball.h"
#include "equipment/swept_ball.h"

namespace olympics::sports::equipment {

// A static axis-aligned box the ball bounces off.
struct ArenaBox {
  int id = 0;  // the caller's name for it, reported in contacts
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  double restitution = 0.5;
  double friction = 0.3;
};

// A disc moving over this step from `from` to `to` (e.g. a racket head).
struct MovingDisc {
  int id = 0;
  Disc disc;
  Pose from, to;
  double restitution = 0.8;
  double friction = 0.8;
};

enum class SurfaceKind { Ground, Box, Disc };

struct BallContact {
  SurfaceKind kind = SurfaceKind::Ground;
  int id = 0;              // the ArenaBox / MovingDisc id (0 for the ground)
  double time = 0;         // seconds into the step
  Eigen::Vector3d centre;  // ball centre at contact
  Eigen::Vector3d normal;  // unit, from the surface towards the ball
  Eigen::Vector3d v_before, v_after;
  double approach_speed = 0;  // normal speed towards the surface, m/s (> 0)
};

class BallFlight {
 public:
  explicit BallFlight(const BallSpec& spec, double ground_restitution, double ground_friction);

  void set_state(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity);
  const Eigen::Vector3d& position() const { return position_; }
  const Eigen::Vector3d& velocity() const { return velocity_; }
  const BallSpec& spec() const { return spec_; }

  // Gravity plus quadratic drag at velocity v.
  Eigen::Vector3d acceleration(const Eigen::Vector3d& v) const;

  // Advances dt seconds; appends the contacts of this step, in time order, to `contacts`.
  void step(double dt, std::span<const ArenaBox> boxes, std::span<const MovingDisc> discs,
            std::vector<BallContact>& contacts);

  // Below this approach speed a contact does not bounce: the ball rolls or rests on the surface.
  static constexpr double kRestingSpeed = 0.05;  // m/s
  // Friction cannot slow the sliding contact past rolling: a hollow ball (I = 2/3 m r^2) keeps
  // 3/5 of its tangential speed (its spin is not tracked).
  static constexpr double kHollowBallRollingLoss = 0.4;

 private:
  BallSpec spec_;
  double ground_restitution_, ground_friction_;
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_ = Eigen::Vector3d::Zero();
};

// Distance from a sphere of `radius` at `centre` to an axis-aligned box (< 0: overlap), and the
// unit normal from the box towards the centre.
double ball_box_distance(const Eigen::Vector3d& centre, double radius, const ArenaBox& box,
                         Eigen::Vector3d* normal = nullptr);

}  // namespace olympics::sports::equipment
