#include "equipment/swept_ball.h"

#include <algorithm>
#include <cmath>

namespace olympics::sports::equipment {
Pose interpolate(const Pose& a, const Pose& b, double t) {
  return {a.position + t * (b.position - a.position), a.orientation.slerp(t, b.orientation)};
}

namespace {

// Closest point of the solid disc to q, in world coordinates.
Eigen::Vector3d closest_point(const Eigen::Vector3d& q, const Disc& disc, const Pose& pose) {
  Eigen::Vector3d local = pose.orientation.conjugate() * (q - pose.position);
  Eigen::Vector2d radial(local.x(), local.y());
  if (radial.norm() > disc.radius) radial *= disc.radius / radial.norm();
  const double z = std::clamp(local.z(), -disc.half_thickness, disc.half_thickness);
  return pose.position + pose.orientation * Eigen::Vector3d(radial.x(), radial.y(), z);
}

// Closest point of the solid box to q, in world coordinates.
Eigen::Vector3d closest_point(const Eigen::Vector3d& q, const Box& box, const Pose& pose) {
  const Eigen::Vector3d local = pose.orientation.conjugate() * (q - pose.position);
  const Eigen::Vector3d clamped = local.cwiseMax(-box.half_extents).cwiseMin(box.half_extents);
  return pose.position + pose.orientation * clamped;
}

// The normal where no closest point is apart from the centre (the centre inside the solid).
Eigen::Vector3d fallback_normal(const Disc&, const Pose& pose) {
  return pose.orientation * Eigen::Vector3d::UnitZ();
}
Eigen::Vector3d fallback_normal(const Box&, const Pose& pose) {
  return pose.orientation * Eigen::Vector3d::UnitX();
}

double reach(const Disc& disc) { return std::hypot(disc.radius, disc.half_thickness); }
double reach(const Box& box) { return box.half_extents.norm(); }

// Conservative advancement of the ball against a moving solid (a Disc or a Box).
template <typename Solid>
std::optional<SweptHit> sweep(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                              double ball_radius, const Solid& solid, const Pose& pose0,
                              const Pose& pose1, double dt, double tolerance) {
  // Bound on how fast the distance can shrink: the ball's speed plus the fastest point of the
  // solid (centre speed + spin x the solid's farthest reach).
  const Eigen::Vector3d ball_v = (p1 - p0) / dt;
  const Eigen::Vector3d centre_v = (pose1.position - pose0.position) / dt;
  const Eigen::AngleAxisd turn(pose0.orientation.conjugate() * pose1.orientation);
  const double spin = std::abs(turn.angle()) / dt;
  const double closing_bound =
      (ball_v.norm() + centre_v.norm() + spin * reach(solid)) * dt;  // per unit t
  double t = 0;
  for (int iteration = 0; iteration < 1000000; ++iteration) {  // grazing contacts converge slowly
    const Pose pose = interpolate(pose0, pose1, t);
    const Eigen::Vector3d centre = p0 + t * (p1 - p0);
    const Eigen::Vector3d on_solid = closest_point(centre, solid, pose);
    const double d = (centre - on_solid).norm() - ball_radius;
    if (d <= tolerance) {
      SweptHit hit;
      hit.t = t;
      hit.ball_centre = centre;
      hit.normal = (centre - on_solid).norm() > 1e-12 ? (centre - on_solid).normalized()
                                                      : fallback_normal(solid, pose);
      // The solid's velocity at the contact point: its centre's plus spin x lever.
      const Eigen::Vector3d omega = pose0.orientation * (turn.axis() * (turn.angle() / dt));
      hit.surface_point_velocity = centre_v + omega.cross(on_solid - pose.position);
      return hit;
    }
    if (closing_bound <= 0) return std::nullopt;
    t += d / closing_bound;  // cannot pass the first contact
    if (t > 1) return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace

double ball_disc_distance(const Eigen::Vector3d& centre, double ball_radius, const Disc& disc,
                          const Pose& pose) {
  return (centre - closest_point(centre, disc, pose)).norm() - ball_radius;
}

std::optional<SweptHit> sweep_ball_disc(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                        double ball_radius, const Disc& disc, const Pose& pose0,
                                        const Pose& pose1, double dt, double tolerance) {
  return sweep(p0, p1, ball_radius, disc, pose0, pose1, dt, tolerance);
}

double ball_box_distance(const Eigen::Vector3d& centre, double ball_radius, const Box& box,
                         const Pose& pose) {
  return (centre - closest_point(centre, box, pose)).norm() - ball_radius;
}

std::optional<SweptHit> sweep_ball_box(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                       double ball_radius, const Box& box, const Pose& pose0,
                                       const Pose& pose1, double dt, double tolerance) {
  return sweep(p0, p1, ball_radius, box, pose0, pose1, dt, tolerance);
}

Eigen::Vector3d bounce(const Eigen::Vector3d& ball_velocity,
                       const Eigen::Vector3d& surface_velocity, const Eigen::Vector3d& normal,
                       double restitution, double friction, double max_tangential_loss) {
  const Eigen::Vector3d relative = ball_velocity - surface_velocity;
  const double vn = relative.dot(normal);
  if (vn >= 0) return ball_velocity;  // separating already
  const Eigen::Vector3d tangential = relative - vn * normal;
  const double normal_change = -(1 + restitution) * vn;  // > 0
  const double tangential_speed = tangential.norm();
  const double tangential_change =
      std::min(friction * normal_change, max_tangential_loss * tangential_speed);
  Eigen::Vector3d after = relative + normal_change * normal;
  if (tangential_speed > 0) after -= tangential_change * tangential / tangential_speed;
  return surface_velocity + after;
}

}  // namespace olympics::sports::equipment
