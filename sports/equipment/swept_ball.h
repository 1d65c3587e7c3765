// Continuous collision of a fast ball with a thin moving disc (a racket head or a paddle) or a box
// (a golf club's head), and the bounce. ODE has no continuous collision: a 50 m/s ball moves 0.4 m
// per 120 Hz step, far more than a racket is thick, and a 40 m/s driver head moves 0.33 m, far
// more than it and the ball are thick. So the ball is swept along its step against the disc or box
// moving over the same step (position interpolated, orientation slerped), by conservative
// advancement on the exact distance to the solid, which cannot step over a contact.
#pragma once

#include <Eigen/Geometry>
#include <optional>

namespace olympics::sports::equipment {

struct Disc {
  double radius = 0.15;          // m
  double half_thickness = 0.02;  // m; the disc's axis is its local z
};

struct Box {
  Eigen::Vector3d half_extents = Eigen::Vector3d::Zero();  // m, along the box's local axes
};

struct Pose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

struct SweptHit {
  double t = 0;                            // fraction of the step, in [0, 1]
  Eigen::Vector3d ball_centre;             // at contact
  Eigen::Vector3d normal;                  // unit, from the solid towards the ball
  Eigen::Vector3d surface_point_velocity;  // the solid's velocity at the contact point
};

// The pose a fraction t of the way from a to b (position lerp, orientation slerp).
Pose interpolate(const Pose& a, const Pose& b, double t);

// Distance from a sphere centre to the solid disc at `pose`, minus the sphere radius (< 0:
// overlap).
double ball_disc_distance(const Eigen::Vector3d& centre, double ball_radius, const Disc& disc,
                          const Pose& pose);

// The first contact of a ball moving from p0 to p1 with the disc moving from pose0 to pose1 over a
// step of dt seconds; nullopt when they do not touch (contacts within `tolerance` metres count).
std::optional<SweptHit> sweep_ball_disc(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                        double ball_radius, const Disc& disc, const Pose& pose0,
                                        const Pose& pose1, double dt, double tolerance = 1e-4);

// Distance from a sphere centre to the solid box at `pose`, minus the sphere radius (< 0:
// overlap).
double ball_box_distance(const Eigen::Vector3d& centre, double ball_radius, const Box& box,
                         const Pose& pose);

// The first contact of a ball moving from p0 to p1 with the box moving from pose0 to pose1, as
// sweep_ball_disc.
std::optional<SweptHit> sweep_ball_box(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                       double ball_radius, const Box& box, const Pose& pose0,
                                       const Pose& pose1, double dt, double tolerance = 1e-4);

// The ball's velocity after bouncing off a much heavier surface moving with `surface_velocity` at
// the contact: the normal part of the relative velocity is reversed and scaled by `restitution`,
// the tangential part is reduced by Coulomb friction (at most `friction` times the normal impulse,
// never past sticking; never past rolling: at most `max_tangential_loss` of the tangential
// speed, 0.4 for a hollow ball, I = 2/3 m r^2, whose spin is not tracked).
Eigen::Vector3d bounce(const Eigen::Vector3d& ball_velocity,
                       const Eigen::Vector3d& surface_velocity, const Eigen::Vector3d& normal,
                       double restitution, double friction, double max_tangential_loss = 1.0);

}  // namespace olympics::sports::equipment
