#include "control/serve_plan.h"

#include <algorithm>
#include <cmath>

namespace olympics::client::control {
namespace {

constexpr int kContactsTried = 6;    // the planner is run at this many meeting points at most
constexpr double kFallWeight = 0.1;  // m of distance from the sweet spot per m/s of fall
constexpr double kTableServeElevation = 0.1;  // radians: table-tennis serves go down or level
// Doubles: the serve may go up this much. The diagonal from the server's place (its right half,
// 0.2 m further back than singles) is longer, and sent level the gentlest legal serve left the
// face at 4.7 m/s, where the arm delivers about 3.5 m/s (measured on tuning seeds 1-4, the ball's
// velocity just after the strike): the ball fell into the net or short. Sent up (0.3 rad), about
// 3.9 m/s (tuning seeds 1-200: 182 of 200 first serves in; 0.45 rad: 186, within noise).
constexpr double kDoublesServeElevation = 0.3;
// Table tennis: the own bounces tried, as fractions of the half's length from the net.
constexpr double kOwnBounceDepths[] = {0.35, 0.5, 0.65, 0.8};
// Doubles: the own bounces tried across the server's right half, in m from the centre line. From
// a toss near the right sideline a ball bounced a quarter of the width in (the diagonal's line)
// runs on along the same line and crosses the net still on the server's side of the centre line
// (tuning seeds 1-20: no shot found from any of the four depths); bounced nearer the centre line
// it crosses it before the net and lands on the receiver's right half.
constexpr double kDoublesOwnBounceYs[] = {0.05, 0.1, 0.15, 0.25};
// Doubles: a serve is planned to land at least this far inside the receiver's right half (the
// centre line is the edge the planner's error would cross).
constexpr double kDoublesLandingInside = 0.08;

// Table-tennis doubles: the serve goes diagonally, from the server's right half to the receiver's.
bool diagonal(const ServeAim& aim) { return aim.own_bounce.y() != 0; }

// Table tennis: a shot sent down onto the own court at `own`, then its path on to the receiver's
// court (checked by the predicted path, with the net and the table); nullopt when it does not
// land there. A shot sent upward would come down steeply and bounce short, on its own court again.
std::optional<ShotPlan> table_serve(const BallPath& path, const BallSample& at,
                                    const Eigen::Vector3d& swing, const Eigen::Vector2d& own,
                                    const ServeAim& aim, double net_margin, double* landing_error) {
  const auto& game = path.game();
  // The own bounce is aimed like any landing, with no net to clear on the way.
  const double elevation = diagonal(aim) ? kDoublesServeElevation : kTableServeElevation;
  auto shot = plan_shot(path, at.position, at.velocity, own, -1e9, swing, elevation);
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
    if (diagonal(aim) && s.position.y() * (aim.landing.y() > 0 ? 1 : -1) < kDoublesLandingInside)
      return std::nullopt;
    *landing_error = (s.position.head<2>() - aim.landing).norm();
    return shot;
  }
  return std::nullopt;
}

}  // namespace

bool hardly_moving_across(const Eigen::Vector3d& velocity) {
  return velocity.head<2>().norm() < 0.5;
}

bool is_toss(const Eigen::Vector3d& ball, const Eigen::Vector3d& velocity,
             const Eigen::Vector3d& root) {
  return ball.x() < 0 && hardly_moving_across(velocity) && (ball - root).head<2>().norm() < 1.5;
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
    // Between the net and the service line, on the far side of the centre line (both halves
    // from the middle).
    const double in = kServeBoxInside, side = game.half_width_singles - in;
    aim.box = {{in, across > 0 ? in : -side}, {game.service_line - in, across < 0 ? -in : side}};
  }
  return aim;
}

namespace {

// On the toss's path the falling, untouched points whose face position lies within reach of the
// shoulder: nearest the sweet spot first, at most kContactsTried.
std::vector<const BallSample*> serve_contacts(const std::vector<BallSample>& toss,
                                              const Eigen::Vector3d& shoulder, double reach,
                                              double face_back, const Eigen::Vector3d& sweet_spot,
                                              double min_time) {
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
  std::vector<const BallSample*> contacts;
  for (const auto& c : candidates) contacts.push_back(c.second);
  return contacts;
}

}  // namespace

std::optional<ServePlan> plan_serve(const BallPath& path, const std::vector<BallSample>& toss,
                                    const Eigen::Vector3d& shoulder, double reach, double face_back,
                                    const Eigen::Vector3d& sweet_spot, const ServeAim& aim,
                                    double net_margin, double min_time) {
  const auto& game = path.game();
  for (const BallSample* at :
       serve_contacts(toss, shoulder, reach, face_back, sweet_spot, min_time)) {
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
    // Singles: the own bounce's line is the aim's; doubles: across the server's right half.
    std::vector<double> own_ys = {aim.own_bounce.y()};
    if (diagonal(aim)) {
      own_ys.clear();
      for (double y : kDoublesOwnBounceYs) own_ys.push_back(aim.own_bounce.y() > 0 ? y : -y);
    }
    for (double own_y : own_ys)
      for (double depth : kOwnBounceDepths) {
        const Eigen::Vector2d own(-depth * game.half_length, own_y);
        double error = 0;
        auto shot = table_serve(path, *at, swing, own, aim, net_margin, &error);
        if (shot && error < best_error) best = shot, best_error = error;
      }
    if (best) return ServePlan{*at, *best};
  }
  return std::nullopt;
}

std::optional<ServePlan> plan_arc_serve(const BallPath& path, const std::vector<BallSample>& toss,
                                        const Eigen::Vector3d& shoulder, double reach,
                                        double face_back, const Eigen::Vector3d& sweet_spot,
                                        const ServeAim& aim, double net_margin, double min_time,
                                        const std::vector<double>& speeds) {
  for (const BallSample* at :
       serve_contacts(toss, shoulder, reach, face_back, sweet_spot, min_time)) {
    const auto tangent = arc_tangent(at->position - Eigen::Vector3d(face_back, 0, 0), shoulder);
    if (!tangent) continue;
    for (double speed : speeds)
      if (auto shot = plan_shot_at_speed(path, at->position, at->velocity, speed * *tangent,
                                         aim.landing, net_margin, aim.box))
        return ServePlan{*at, *shot};
  }
  return std::nullopt;
}

}  // namespace olympics::client::control
