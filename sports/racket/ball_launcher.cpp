#include "racket/ball_launcher.h"

#include <cmath>
#include <stdexcept>

namespace olympics::sports::racket {
namespace {

constexpr double kDt = 1.0 / 240.0;
constexpr double kNetMargin = 0.03;  // m of air between ball and net top

struct Flight {
  double range = 0;  // horizontal distance travelled to the landing
  bool cleared_net = true;
};

// Flies a drag-affected ball from `from` until it comes down to the landing height.
Flight fly(const RacketGame& game, const equipment::BallFlight& model, const Eigen::Vector3d& from,
           const Eigen::Vector3d& v0) {
  Eigen::Vector3d p = from, v = v0;
  const double land_z = game.surface_height + game.ball.radius;
  const double net_z = game.net_height + game.ball.radius + kNetMargin;
  Flight f;
  for (int i = 0; i < 240 * 10; ++i) {
    const Eigen::Vector3d v1 = v + model.acceleration(v) * kDt;
    const Eigen::Vector3d p1 = p + 0.5 * (v + v1) * kDt;
    if (p.x() * p1.x() < 0) {  // crossing the net plane
      const double s = p.x() / (p.x() - p1.x());
      if (p.z() + s * (p1.z() - p.z()) < net_z) f.cleared_net = false;
    }
    if (p1.z() <= land_z && v1.z() < 0) {
      const double s = (p.z() - land_z) / (p.z() - p1.z());
      const Eigen::Vector3d at = p + s * (p1 - p);
      f.range = (at - from).head<2>().norm();
      return f;
    }
    p = p1;
    v = v1;
  }
  f.range = 1e9;
  return f;
}

// Depth is a fraction of the half's length from the net, in [depth_lo, depth_hi].
Eigen::Vector2d uniform_point_in_half(const RacketGame& game, int team, double y_lo, double y_hi,
                                      std::mt19937_64& rng, double depth_lo = 0.05,
                                      double depth_hi = 1.0) {
  const double depth =
      std::uniform_real_distribution<double>(depth_lo, depth_hi)(rng) * game.half_length;
  const double y = std::uniform_real_distribution<double>(y_lo, y_hi)(rng);
  return {RacketGame::side_sign(team) * depth, y};
}

Launch draw_launch(const RacketGame& game, const Eigen::Vector3d& from, int team, double y_lo,
                   double y_hi, double speed_lo, double speed_hi, std::mt19937_64& rng,
                   double depth_lo = 0.05, double depth_hi = 1.0) {
  for (int attempt = 0; attempt < 200; ++attempt) {
    const Eigen::Vector2d target =
        uniform_point_in_half(game, team, y_lo, y_hi, rng, depth_lo, depth_hi);
    const double speed = std::uniform_real_distribution<double>(speed_lo, speed_hi)(rng);
    if (auto launch = aim_ball(game, from, target, speed)) return *launch;
  }
  throw std::logic_error(game.sport + ": no launch clears the net; check the launcher settings");
}

}  // namespace

std::optional<Launch> aim_ball(const RacketGame& game, const Eigen::Vector3d& from,
                               const Eigen::Vector2d& target, double horizontal_speed) {
  const equipment::BallFlight model(game.ball, game.ball.restitution, game.ball.friction);
  const Eigen::Vector2d offset = target - from.head<2>();
  const double distance = offset.norm();
  const Eigen::Vector2d dir = offset / distance;
  auto velocity = [&](double vz) {
    return Eigen::Vector3d(dir.x() * horizontal_speed, dir.y() * horizontal_speed, vz);
  };
  // Range grows with the vertical speed over this interval (angles well below 45 degrees).
  double lo = -horizontal_speed * 0.3, hi = horizontal_speed * 0.8;
  if (fly(game, model, from, velocity(lo)).range > distance ||
      fly(game, model, from, velocity(hi)).range < distance)
    return std::nullopt;
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (lo + hi);
    (fly(game, model, from, velocity(mid)).range < distance ? lo : hi) = mid;
  }
  const Eigen::Vector3d v = velocity(0.5 * (lo + hi));
  if (!fly(game, model, from, v).cleared_net) return std::nullopt;
  return Launch{from, v, target};
}

Launch ball_return_launch(const RacketGame& game, int team, std::mt19937_64& rng) {
  const double y = std::uniform_real_distribution<double>(-game.launch_y, game.launch_y)(rng);
  const Eigen::Vector3d from(-RacketGame::side_sign(team) * game.launch_x, y, game.launch_z);
  const double w = game.half_width_singles;
  return draw_launch(game, from, team, -w, w, game.launch_speed_lo, game.launch_speed_hi, rng);
}

Launch feed_launch(const RacketGame& game, int team, int receiver_y_sign, bool doubles,
                   std::mt19937_64& rng) {
  const Eigen::Vector3d from(0, 0, game.feed_z);
  const double w = game.half_width(doubles);
  const double y_lo = doubles ? (receiver_y_sign > 0 ? 0.0 : -w) : -w;
  const double y_hi = doubles ? (receiver_y_sign > 0 ? w : 0.0) : w;
  return draw_launch(game, from, team, y_lo, y_hi, game.feed_speed_lo, game.feed_speed_hi, rng);
}

Launch feed_to_player_launch(const RacketGame& game, int team, double receiver_y,
                             std::mt19937_64& rng) {
  const Eigen::Vector3d from(0, 0, game.feed_z);
  const double spread = 0.15 * game.half_width_singles;
  return draw_launch(game, from, team, receiver_y - spread, receiver_y + spread, game.feed_speed_lo,
                     game.feed_speed_hi, rng, 0.55, 0.9);
}

}  // namespace olympics::sports::racket
