#include "control/ball_path.h"

#include <cmath>

namespace olympics::client::control {

using sports::equipment::BallContact;
using sports::equipment::BallFlight;
using sports::equipment::SurfaceKind;

namespace {
Eigen::Matrix3d yaw_rotation(double yaw) {
  return Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}
}  // namespace

Eigen::Vector3d CourtFrame::point(const Eigen::Vector3d& p) const {
  return root + yaw_rotation(yaw) * p;
}
Eigen::Vector3d CourtFrame::vector(const Eigen::Vector3d& v) const { return yaw_rotation(yaw) * v; }
Eigen::Vector3d CourtFrame::to_heading_point(const Eigen::Vector3d& p) const {
  return yaw_rotation(-yaw) * (p - root);
}
Eigen::Vector3d CourtFrame::to_heading_vector(const Eigen::Vector3d& v) const {
  return yaw_rotation(-yaw) * v;
}

BallPath::BallPath(const sports::racket::RacketGame& game) : game_(game), arena_(game.arena()) {}

std::vector<BallSample> BallPath::predict(const Eigen::Vector3d& position,
                                          const Eigen::Vector3d& velocity, double horizon_s,
                                          int own_bounces) const {
  BallFlight flight(game_.ball, game_.ball.restitution, game_.ball.friction);
  flight.set_state(position, velocity);
  std::vector<BallSample> out;
  std::vector<BallContact> contacts;
  BallSample s;
  s.own_bounces = own_bounces;
  const double surface_top = game_.surface_height;
  for (int i = 1; i * kStep_s <= horizon_s + 1e-9; ++i) {
    contacts.clear();
    flight.step(kStep_s, arena_, {}, contacts);
    for (const BallContact& c : contacts) {
      const bool on_surface = game_.on_table
                                  ? c.kind == SurfaceKind::Box && c.id == sports::racket::kTable &&
                                        c.centre.z() > surface_top
                                  : c.kind == SurfaceKind::Ground;
      if (on_surface && c.centre.x() < 0)
        ++s.own_bounces;
      else if (c.kind != SurfaceKind::Box || c.id != sports::racket::kNet)
        ++s.other_bounces;
    }
    s.time = i * kStep_s;
    s.position = flight.position();
    s.velocity = flight.velocity();
    out.push_back(s);
  }
  return out;
}

BallPath::Flight BallPath::fly(const Eigen::Vector3d& position,
                               const Eigen::Vector3d& velocity) const {
  BallFlight flight(game_.ball, game_.ball.restitution, game_.ball.friction);
  const double r = game_.ball.radius;
  const double floor = game_.surface_height + r;
  Flight f;
  Eigen::Vector3d p = position, v = velocity;
  for (int i = 0; i < 600; ++i) {
    const Eigen::Vector3d v1 = v + flight.acceleration(v) * kStep_s;
    const Eigen::Vector3d p1 = p + 0.5 * (v + v1) * kStep_s;
    if (p.x() < 0 && p1.x() >= 0) {
      const double s = -p.x() / (p1.x() - p.x());
      f.net_clearance = p.z() + s * (p1.z() - p.z()) - r - game_.net_height;
    }
    if (p1.z() <= floor && v1.z() < 0) {
      const double s = (p.z() - floor) / (p.z() - p1.z());
      f.landing = (p + s * (p1 - p)).head<2>();
      f.seconds = (i + s) * kStep_s;
      f.lands = true;
      return f;
    }
    p = p1;
    v = v1;
  }
  return f;
}

}  // namespace olympics::client::control
