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

}  // namespace

double ball_disc_distance(const Eigen::Vector3d& centre, double ball_radius, const Disc& disc,
                          const Pose& pose) {
  return (centre - closest_point(centre, disc, pose)).norm() - ball_radius;
}

std::optional<SweptHit> sweep_ball_disc(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                        double ball_radius, const Disc& disc, const Pose& pose0,
                                        const Pose& pose1, double dt, double tolerance) {
  // Bound on how fast the distance can shrink: the ball's speed plus the fastest point of the
  // disc (centre speed + spin x the disc's farthest reach).
  const Eigen::Vector3d ball_v = (p1 - p0) / dt;
  const Eigen::Vector3d centre_v = (pose1.position - pose0.position) / dt;
  const Eigen::AngleAxisd turn(pose0.orientation.conjugate() * pose1.orientation);
  const double spin = std::abs(turn.angle()) / dt;
  const double reach = std::hypot(disc.radius, disc.half_thickness);
  const double closing_bound = (ball_v.norm() + centre_v.norm() + spin * reach) * dt;  // per unit t
  double t = 0;
  for (int iteration = 0; iteration < 1000000; ++iteration) {  // grazing contacts converge slowly
    const Pose pose = interpolate(pose0, pose1, t);
    const Eigen::Vector3d centre = p0 + t * (p1 - p0);
    const double d = ball_disc_distance(centre, ball_radius, disc, pose);
    if (d <= tolerance) {
      SweptHit hit;
      hit.t = t;
      hit.ball_centre = centre;
      const Eigen::Vector3d on_disc = closest_point(centre, disc, pose);
      hit.normal = (centre - on_disc).norm() > 1e-12 ? (centre - on_disc).normalized()
                                                     : pose.orientation * Eigen::Vector3d::UnitZ();
      // The disc's velocity at the contact point: its centre's plus spin x lever.
      const Eigen::Vector3d omega = pose0.orientation * (turn.axis() * (turn.angle() / dt));
      hit.disc_point_velocity = centre_v + omega.cross(on_disc - pose.position);
      return hit;
    }
    if (closing_bound <= 0) return std::nullopt;
    t += d / closing_bound;  // cannot pass the first contact
    if (t > 1) return std::nullopt;
  }
  return std::nullopt;
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
