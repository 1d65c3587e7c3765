// Planning a racket stroke: where to meet the ball, and the face's normal and speed that send it
// over the net to a chosen landing point.
//
// The face bounces the ball as the server does (sports/equipment/swept_ball.h `bounce`): the
// normal part of the velocity relative to the face is reversed and scaled by the restitution,
// the tangential part slowed by friction. Given the ball's velocity at contact and the velocity it
// should leave with, the face's normal and its speed along that normal are solved by Newton's
// method on that bounce; the outgoing velocity is chosen among launch elevations (each solved
// for speed by bisection on the drag flight) as the one that asks for the gentlest stroke.
#pragma once

#include <Eigen/Geometry>
#include <optional>

#include "control/ball_path.h"

namespace olympics::client::control {

struct FaceMotion {
  Eigen::Vector3d normal{1, 0, 0};     // unit, toward the ball's side (court frame)
  Eigen::Vector3d direction{1, 0, 0};  // unit: the face moves along it (the swing's line)
  double speed = 0;                    // face speed along `direction`, m/s
  Eigen::Vector3d ball_out{0, 0, 0};   // the velocity the bounce model then gives
};

// The face motion that turns `ball_in` into `ball_out` (restitution e, friction mu): the face
// swung along `direction` (zero: along its own normal, a pure push).
FaceMotion face_motion_for(const Eigen::Vector3d& ball_in, const Eigen::Vector3d& ball_out,
                           double restitution, double friction,
                           const Eigen::Vector3d& direction = Eigen::Vector3d::Zero());

struct ShotPlan {
  Eigen::Vector3d ball_out;  // velocity the ball should leave the face with
  FaceMotion face;
  BallPath::Flight flight;
};

// From `from` (ball centre at contact, court frame), arriving at `ball_in`: the shot that lands
// at `target` (on the far half) and clears the net by at least `net_margin` m, with the least face
// speed; nullopt when no elevation (up to `max_elevation` radians) does.
std::optional<ShotPlan> plan_shot(const BallPath& path, const Eigen::Vector3d& from,
                                  const Eigen::Vector3d& ball_in, const Eigen::Vector2d& target,
                                  double net_margin,
                                  const Eigen::Vector3d& swing = Eigen::Vector3d::Zero(),
                                  double max_elevation = 1.0);

// Where a shot must come down: a rectangle of the court (court frame, x from `lo` to `hi`).
struct LandingArea {
  Eigen::Vector2d lo{0, 0}, hi{0, 0};
  bool contains(const Eigen::Vector2d& p) const {
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
  }
};

// A face swung at a speed the arm can deliver: from `from`, arriving at `ball_in`, the face moving
// at `face_velocity` (court frame), the normal (searched on a grid of azimuths and elevations)
// whose return clears the net by `net_margin` and lands in `area`, nearest `target`; nullopt when
// none does.
std::optional<ShotPlan> plan_shot_at_speed(const BallPath& path, const Eigen::Vector3d& from,
                                           const Eigen::Vector3d& ball_in,
                                           const Eigen::Vector3d& face_velocity,
                                           const Eigen::Vector2d& target, double net_margin,
                                           const LandingArea& area);
// ...landing inside the far half, at least `inside` m from its lines.
std::optional<ShotPlan> plan_shot_at_speed(const BallPath& path, const Eigen::Vector3d& from,
                                           const Eigen::Vector3d& ball_in,
                                           const Eigen::Vector3d& face_velocity,
                                           const Eigen::Vector2d& target, double net_margin,
                                           double inside);

// An arc swing (the arm turning as one about the vertical through `pivot`,
// scripted_tennis_swing.h): the unit direction a face at `face` moves in, taken toward the net
// (+x); nullopt where the arc runs across the court there (less than half of it toward the net) or
// the face is within 0.2 m of the pivot's vertical (the turn would have to be too quick).
std::optional<Eigen::Vector3d> arc_tangent(const Eigen::Vector3d& face,
                                           const Eigen::Vector3d& pivot);

}  // namespace olympics::client::control
