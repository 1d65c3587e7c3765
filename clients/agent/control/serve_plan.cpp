#include "control/serve_plan.h"

#include <algorithm>
#include <cmath>

namespace olympics::client::control {
namespace {

constexpr int kContactsTried = 6;    // the planner is run at this many meeting points at most
constexpr double kFallWeight = 0.1;  // m of distance from the sweet spot per m/s of fall
constexpr double kTableServeElevation = 0.1;  // radians: table-tennis serves go down or level
// Table tennis: the own bounces tried, as fractions of the half's length from the net.
constexpr double kOwnBounceDepths[] = {0.35, 0.5, 0.65, 0.8};

// Table tennis: a shot sent down onto the own court at `own`, then its path on to the receiver's
// court (checked by the predicted path, with the net and the table); nullopt when it does not
// land there. A shot sent upward would come down steeply and bounce short, on its own court again.
std::optional<ShotPlan> table_serve(const BallPath& path, const BallSample& at,
                                    const Eigen::Vector3d& swing, const Eigen::Vector2d& own,
                                    const ServeAim& aim, double net_margin, double* landing_error) {
  const auto& game = path.game();
  // The own bounce is aimed like any landing, with no net to clear on the way.
  auto shot = plan_shot(path, at.position, at.velocity, own, -1e9, swing, kTableServeElevation);
  if (!shot) return std::nullopt;
  const std::vector<BallSample> after = path.predict(at.position, shot->ball_out, 2.0);
  double over_net = -1e9;
  for (size_t i = 1; i < after.size(); ++i) {
    const BallSample& s = after[i];
    if (after[i - 1].position.x() < 0 && s.position.x() >= 0)
      over_net = s.position.z() - game.ball.radius - game.net_height;
    if (s.own_bounces > 1) return std::nullopt;  // twice on its own court
    if (s.other_bounces == 0) continue;
    // Its first touch beyond: the receiver's court (the table, not the floor), over the net.
    const bool on_table = s.position.z() > game.surface_height;
    if (s.own_bounces != 1 || !on_table || s.position.x() <= 0 || over_net < net_margin)
      return std::nullopt;
    if (aim.landing.y() != 0 && s.position.y() * aim.landing.y() < 0) return std::nullopt;
    *landing_error = (s.position.head<2>() - aim.landing).norm();
    return shot;
  }
  return std::nullopt;
}

}  // namespace

bool is_toss(const Eigen::Vector3d& ball, const Eigen::Vector3d& velocity,
             const Eigen::Vector3d& root) {
  return ball.x() < 0 && velocity.head<2>().norm() < 0.5 && (ball - root).head<2>().norm() < 1.5;
}

ServeAim serve_aim(const sports::racket::RacketGame& game, const Eigen::Vector3d& root) {
  // Diagonally across from the server's side of the centre line.
  const double across = std::abs(root.y()) < 0.1 ? 0.0 : (root.y() > 0 ? -1.0 : 1.0);
  ServeAim aim;
  if (game.on_table) {
    const double quarter = 0.5 * game.half_width_singles;
    aim.own_bounce = {-0.5 * game.half_length, -across * quarter};
    aim.landing = {0.6 * game.half_length, across * quarter};
  } else {
    aim.landing = {0.65 * game.service_line, across * 0.5 * game.half_width_singles};
  }
  return aim;
}

std::optional<ServePlan> plan_serve(const BallPath& path, const std::vector<BallSample>& toss,
                                    const Eigen::Vector3d& shoulder, double reach, double face_back,
                                    const Eigen::Vector3d& sweet_spot, const ServeAim& aim,
                                    double net_margin, double min_time) {
  const auto& game = path.game();
  // Falling, untouched, within reach: nearest the sweet spot first.
  std::vector<std::pair<double, const BallSample*>> candidates;
  for (const BallSample& s : toss) {
    if (s.time < min_time || s.velocity.z() > 0 || s.own_bounces + s.other_bounces > 0) continue;
    const Eigen::Vector3d face = s.position - Eigen::Vector3d(face_back, 0, 0);
    if ((face - shoulder).norm() > reach) continue;
    // A ball falling fast is met late by an arm that lags: slower ones first.
    candidates.push_back({(face - sweet_spot).norm() + kFallWeight * -s.velocity.z(), &s});
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  if (candidates.size() > kContactsTried) candidates.resize(kContactsTried);
  for (const auto& [distance, at] : candidates) {
    const Eigen::Vector2d toward = (aim.landing - at->position.head<2>()).normalized();
    const Eigen::Vector3d swing(toward.x(), toward.y(), 0);
    if (!game.on_table) {
      if (auto shot = plan_shot(path, at->position, at->velocity, aim.landing, net_margin, swing))
        return ServePlan{*at, *shot};
      continue;
    }
    // The own bounce that sends it nearest the aimed landing.
    std::optional<ShotPlan> best;
    double best_error = 1e9;
    for (double depth : kOwnBounceDepths) {
      const Eigen::Vector2d own(-depth * game.half_length, aim.own_bounce.y());
      double error = 0;
      auto shot = table_serve(path, *at, swing, own, aim, net_margin, &error);
      if (shot && error < best_error) best = shot, best_error = error;
    }
    if (best) return ServePlan{*at, *best};
  }
  return std::nullopt;
}

}  // namespace olympics::client::control
