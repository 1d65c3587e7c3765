#include "control/stroke_plan.h"

#include <cmath>
#include <limits>

#include "equipment/ball_flight.h"
#include "equipment/swept_ball.h"

namespace olympics::client::control {
namespace {

Eigen::Vector3d bounce_off(const Eigen::Vector3d& in, const Eigen::Vector3d& n,
                           const Eigen::Vector3d& face_velocity, double e, double mu) {
  return sports::equipment::bounce(in, face_velocity, n, e, mu,
                                   sports::equipment::BallFlight::kHollowBallRollingLoss);
}

// Normal from two angles (azimuth about z from +x, elevation).
Eigen::Vector3d normal_of(double azimuth, double elevation) {
  return {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
          std::sin(elevation)};
}

}  // namespace

FaceMotion face_motion_for(const Eigen::Vector3d& in, const Eigen::Vector3d& out, double e,
                           double mu, const Eigen::Vector3d& direction) {
  const bool along_normal = direction.norm() < 1e-9;
  auto swing = [&](const Eigen::Vector3d& n) -> Eigen::Vector3d {
    return along_normal ? n : direction.normalized();
  };
  // Without friction the impulse is along the normal: n || (out - in), and the normal speeds
  // give the face's. Friction then bends it a little; Newton corrects.
  Eigen::Vector3d n = (out - in).normalized();
  Eigen::Vector3d x(std::atan2(n.y(), n.x()), std::asin(std::clamp(n.z(), -1.0, 1.0)),
                    (out.dot(n) + e * in.dot(n)) / (1 + e) / std::max(0.2, swing(n).dot(n)));
  auto residual = [&](const Eigen::Vector3d& u) {
    const Eigen::Vector3d normal = normal_of(u[0], u[1]);
    return Eigen::Vector3d(bounce_off(in, normal, u[2] * swing(normal), e, mu) - out);
  };
  for (int it = 0; it < 12; ++it) {
    const Eigen::Vector3d r = residual(x);
    if (r.norm() < 1e-6) break;
    Eigen::Matrix3d J;
    for (int k = 0; k < 3; ++k) {
      Eigen::Vector3d d = x;
      d[k] += 1e-6;
      J.col(k) = (residual(d) - r) / 1e-6;
    }
    const Eigen::Vector3d step = J.colPivHouseholderQr().solve(-r);
    if (!step.allFinite()) break;
    x += step.cwiseMax(-0.3).cwiseMin(0.3);
  }
  FaceMotion f;
  f.normal = normal_of(x[0], x[1]);
  f.direction = swing(f.normal);
  f.speed = x[2];
  f.ball_out = bounce_off(in, f.normal, f.speed * f.direction, e, mu);
  return f;
}

std::optional<ShotPlan> plan_shot(const BallPath& path, const Eigen::Vector3d& from,
                                  const Eigen::Vector3d& ball_in, const Eigen::Vector2d& target,
                                  double net_margin, const Eigen::Vector3d& swing,
                                  double max_elevation) {
  const auto& game = path.game();
  const Eigen::Vector2d ahead = target - from.head<2>();
  const double distance = ahead.norm();
  if (distance < 0.1 || ahead.x() <= 0) return std::nullopt;
  const Eigen::Vector2d dir = ahead / distance;
  std::optional<ShotPlan> best;
  double best_cost = std::numeric_limits<double>::infinity();
  for (double elevation = -0.3; elevation <= max_elevation + 1e-9; elevation += 0.05) {
    const Eigen::Vector3d unit(dir.x() * std::cos(elevation), dir.y() * std::cos(elevation),
                               std::sin(elevation));
    // Bisection on speed: further with more speed at one elevation.
    double lo = 0.5, hi = 60;
    BallPath::Flight f;
    for (int it = 0; it < 30; ++it) {
      const double mid = 0.5 * (lo + hi);
      f = path.fly(from, mid * unit);
      const double carry = f.lands ? (f.landing - from.head<2>()).dot(dir) : 1e9;
      (carry < distance ? lo : hi) = mid;
    }
    const Eigen::Vector3d out = 0.5 * (lo + hi) * unit;
    f = path.fly(from, out);
    if (!f.lands || std::abs((f.landing - target).norm()) > 0.05) continue;
    if (f.net_clearance < net_margin) continue;
    const FaceMotion face =
        face_motion_for(ball_in, out, game.equipment.restitution, game.equipment.friction, swing);
    if ((face.ball_out - out).norm() > 0.05 || face.normal.x() < 0.2) continue;
    const double cost = std::abs(face.speed);
    if (cost < best_cost) {
      best_cost = cost;
      best = ShotPlan{out, face, f};
    }
  }
  return best;
}

std::optional<ShotPlan> plan_shot_at_speed(const BallPath& path, const Eigen::Vector3d& from,
                                           const Eigen::Vector3d& ball_in,
                                           const Eigen::Vector3d& face_velocity,
                                           const Eigen::Vector2d& target, double net_margin,
                                           double inside) {
  const auto& game = path.game();
  const double side = game.half_width(false) - inside;
  return plan_shot_at_speed(path, from, ball_in, face_velocity, target, net_margin,
                            LandingArea{{inside, -side}, {game.half_length - inside, side}});
}

std::optional<ShotPlan> plan_shot_at_speed(const BallPath& path, const Eigen::Vector3d& from,
                                           const Eigen::Vector3d& ball_in,
                                           const Eigen::Vector3d& face_velocity,
                                           const Eigen::Vector2d& target, double net_margin,
                                           const LandingArea& area) {
  const auto& game = path.game();
  const double e = game.equipment.restitution, mu = game.equipment.friction;
  std::optional<ShotPlan> best;
  double best_cost = std::numeric_limits<double>::infinity();
  for (double azimuth = -0.6; azimuth <= 0.6 + 1e-9; azimuth += 0.1)
    for (double elevation = -0.2; elevation <= 0.9 + 1e-9; elevation += 0.04) {
      const Eigen::Vector3d n = normal_of(azimuth, elevation);
      // The face must be coming at the ball, not running from it.
      if ((ball_in - face_velocity).dot(n) >= 0) continue;
      const Eigen::Vector3d out = bounce_off(ball_in, n, face_velocity, e, mu);
      if (out.x() <= 0) continue;
      const BallPath::Flight f = path.fly(from, out);
      if (!f.lands || f.net_clearance < net_margin) continue;
      if (!area.contains(f.landing)) continue;
      const double cost = (f.landing - target).norm();
      if (cost < best_cost) {
        best_cost = cost;
        FaceMotion face;
        face.normal = n;
        face.speed = face_velocity.norm();
        face.direction = face.speed > 1e-9 ? Eigen::Vector3d(face_velocity / face.speed) : n;
        face.ball_out = out;
        best = ShotPlan{out, face, f};
      }
    }
  return best;
}

std::optional<Eigen::Vector3d> arc_tangent(const Eigen::Vector3d& face,
                                           const Eigen::Vector3d& pivot) {
  Eigen::Vector3d radius = face - pivot;
  radius.z() = 0;
  if (radius.norm() <= 0.2) return std::nullopt;
  Eigen::Vector3d tangent = Eigen::Vector3d(-radius.y(), radius.x(), 0).normalized();
  if (tangent.x() < 0) tangent = -tangent;
  if (tangent.x() <= 0.5) return std::nullopt;
  return tangent;
}

}  // namespace olympics::client::control
