#include "equipment/ball_flight.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace olympics::sports::equipment {
namespace {

constexpr double kTolerance = 1e-4;  // m: contacts within this distance count
constexpr double kGravity = 9.81;

// A contact found along the current segment, at fraction s of it.
struct Candidate {
  double s = 2;
  SurfaceKind kind = SurfaceKind::Ground;
  int id = 0;
  Eigen::Vector3d normal, surface_velocity = Eigen::Vector3d::Zero();
  double restitution = 0, friction = 0;
};

}  // namespace

double ball_box_distance(const Eigen::Vector3d& centre, double radius, const ArenaBox& box,
                         Eigen::Vector3d* normal) {
  const Eigen::Vector3d closest = centre.cwiseMax(box.lo).cwiseMin(box.hi);
  const Eigen::Vector3d out = centre - closest;
  if (out.squaredNorm() > 0) {
    if (normal) *normal = out.normalized();
    return out.norm() - radius;
  }
  // Inside: the nearest face decides.
  const Eigen::Vector3d to_lo = centre - box.lo, to_hi = box.hi - centre;
  double depth = 1e300;
  for (int k = 0; k < 3; ++k) {
    for (int side = 0; side < 2; ++side) {
      const double d = side == 0 ? to_lo[k] : to_hi[k];
      if (d < depth) {
        depth = d;
        if (normal) *normal = Eigen::Vector3d::Unit(k) * (side == 0 ? -1.0 : 1.0);
      }
    }
  }
  return -depth - radius;
}

BallFlight::BallFlight(const BallSpec& spec, double ground_restitution, double ground_friction)
    : spec_(spec), ground_restitution_(ground_restitution), ground_friction_(ground_friction) {}

void BallFlight::set_state(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity) {
  position_ = position;
  velocity_ = velocity;
}

Eigen::Vector3d BallFlight::acceleration(const Eigen::Vector3d& v) const {
  const double area = M_PI * spec_.radius * spec_.radius;
  const double k = 0.5 * Ball::kAirDensity * spec_.drag_coefficient * area / spec_.mass;
  return Eigen::Vector3d(0, 0, -kGravity) - k * v.norm() * v;
}

void BallFlight::step(double dt, std::span<const ArenaBox> boxes, std::span<const MovingDisc> discs,
                      std::vector<BallContact>& contacts) {
  const double r = spec_.radius;
  double elapsed = 0;
  // A few contacts per step at most (a racket hit, then the ground...); the cap only guards
  // against a ball wedged between surfaces.
  for (int bounce_count = 0; bounce_count < 8 && elapsed < dt; ++bounce_count) {
    const double remaining = dt - elapsed;
    const Eigen::Vector3d v0 = velocity_;
    const Eigen::Vector3d v1 = v0 + acceleration(v0) * remaining;
    const Eigen::Vector3d p0 = position_;
    const Eigen::Vector3d p1 = p0 + 0.5 * (v0 + v1) * remaining;
    const Eigen::Vector3d seg = p1 - p0;
    const double length = seg.norm();
    auto velocity_at = [&](double s) -> Eigen::Vector3d { return v0 + s * (v1 - v0); };
    auto approaching = [&](double s, const Eigen::Vector3d& n, const Eigen::Vector3d& surface_v) {
      return (velocity_at(s) - surface_v).dot(n) < 0;
    };
    Candidate best;

    // The ground plane z = 0.
    if (p1.z() < p0.z()) {
      const double s = p0.z() <= r + kTolerance ? 0.0 : (p0.z() - r) / (p0.z() - p1.z());
      if (s <= 1) {
        best = {s, SurfaceKind::Ground, 0, Eigen::Vector3d::UnitZ()};
        best.restitution = ground_restitution_;
        best.friction = ground_friction_;
      }
    }
    // Static boxes, by conservative advancement along the segment.
    for (const ArenaBox& box : boxes) {
      double s = 0;
      Eigen::Vector3d n;
      for (int it = 0; it < 200 && s < best.s; ++it) {
        const double d = ball_box_distance(p0 + s * seg, r, box, &n);
        if (d <= kTolerance) {
          if (approaching(s, n, Eigen::Vector3d::Zero()))
            best = {s,           SurfaceKind::Box,        box.id,
                    n,           Eigen::Vector3d::Zero(), box.restitution,
                    box.friction};
          break;
        }
        if (length <= 0) break;
        s += d / length;
        if (s > 1) break;
      }
    }
    // Moving discs over the part of the step that is left.
    const double u0 = elapsed / dt;
    for (const MovingDisc& m : discs) {
      const Pose from = interpolate(m.from, m.to, u0);
      auto hit = sweep_ball_disc(p0, p1, r, m.disc, from, m.to, remaining, kTolerance);
      if (hit && hit->t < best.s && approaching(hit->t, hit->normal, hit->surface_point_velocity))
        best = {hit->t,        SurfaceKind::Disc, m.id, hit->normal, hit->surface_point_velocity,
                m.restitution, m.friction};
    }

    if (best.s > 1) {  // free flight to the end of the step
      position_ = p1;
      velocity_ = v1;
      break;
    }
    BallContact c;
    c.kind = best.kind;
    c.id = best.id;
    c.time = elapsed + best.s * remaining;
    c.centre = p0 + best.s * seg;
    c.normal = best.normal;
    c.v_before = velocity_at(best.s);
    c.approach_speed = -(c.v_before - best.surface_velocity).dot(best.normal);
    c.v_after = bounce(c.v_before, best.surface_velocity, best.normal,
                       c.approach_speed < kRestingSpeed ? 0.0 : best.restitution, best.friction,
                       kHollowBallRollingLoss);
    contacts.push_back(c);
    position_ = c.centre;
    velocity_ = c.v_after;
    elapsed = c.time;
    if (best.s <= 0 && c.approach_speed < kRestingSpeed) {
      // Resting on the surface: rolls along it for the rest of the step, gravity balanced.
      Eigen::Vector3d a = acceleration(velocity_);
      a -= a.dot(best.normal) * best.normal;
      position_ += velocity_ * (dt - elapsed) + 0.5 * a * (dt - elapsed) * (dt - elapsed);
      velocity_ += a * (dt - elapsed);
      break;
    }
  }
  if (position_.z() < r) position_.z() = r;  // never below the ground, whatever happened
}

}  // namespace olympics::sports::equipment
