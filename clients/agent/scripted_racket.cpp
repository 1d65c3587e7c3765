#include "scripted_racket.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "smpl_observation.h"

namespace olympics::client {
namespace {

using namespace smpl;

constexpr double kReachEarly_s = 0.5;  // while walking, the arm stays at rest until this close

struct SportPlay {
  double restitution;  // of the court or table, for the prediction
  double plane;        // hitting plane, m in front of the root
  double ball_radius;
  Eigen::Vector2d reach;  // where the racket meets the ball, relative to the root
  StepGains legs;
};

// Balance gains were found by a grid search over 12 ball-return episodes each (touches, falls):
// the racket's weight on the outstretched arm asks for other gains than the paddle's. Step gains
// by a random search over walks to 10 targets (reach, time, heading, falls).
SportPlay tennis_play() {
  SportPlay p{0.75, 0.3, 0.032, {0.3, -1.05}, {}};
  p.legs.balance = {1.0, 2.0, 0.0, 1.0};
  return p;
}
SportPlay table_play() {
  SportPlay p{0.9, 0.35, 0.02, {0.35, -0.75}, {}};
  p.legs.balance = {0.5, 0.5, -0.2, 2.0};
  return p;
}

struct Crossing {
  bool found = false;
  Eigen::Vector3d point;
  double seconds = 0;
};

// Steps the ball (gravity, one bounce off the surface) until it crosses x = plane coming in.
// Works in the root's frame turned to face the net (`facing` turns heading-frame vectors so),
// which does not sway with the body as the heading frame does.
Crossing predict_crossing(std::span<const float> o, const ScriptedRacketPolicy::Blocks& at,
                          const SportPlay& play, double surface_z, const Eigen::Matrix3d& facing) {
  Eigen::Vector3d p = facing * vec3(o, at.ball), v = facing * vec3(o, at.ball_velocity);
  const double floor_z = surface_z + play.ball_radius;
  Crossing c;
  for (int i = 0; i < 240; ++i) {
    const double dt = 1.0 / 120;
    v.z() -= 9.81 * dt;
    const Eigen::Vector3d next = p + v * dt;
    if (next.z() < floor_z && v.z() < 0) v.z() = -play.restitution * v.z();
    c.seconds += dt;
    if ((p.x() - play.plane) * (next.x() - play.plane) <= 0 && v.x() < 0) {
      c.found = true;
      c.point = next;
      return c;
    }
    p = next;
  }
  return c;
}

// Points the racket at `aim` (root-relative) from the right shoulder, face to the net; `swing`
// from 0 (drawn back) to 1 (through).
void reach(std::span<const float> o, const Eigen::Vector3d& aim, double swing, std::span<float> a) {
  Eigen::Vector3d d = aim - body_position(o, kRShoulder);
  if (d.norm() < 1e-6) d = Eigen::Vector3d(0, -1, 0);
  d.normalize();
  set_joint(a, kRShoulder, 0, std::atan2(-d.z(), -d.y()));
  set_joint(a, kRShoulder, 2, std::asin(std::clamp(d.x(), -1.0, 1.0)) - 0.4 * swing);
  set_joint(a, kRElbow, 0, 0);
  set_joint(a, kRHand, 1, M_PI / 2);  // roll the face towards the net
}

}  // namespace

void ScriptedRacketPolicy::start(const MatchInfo& match) {
  if (match.sport != "tennis" && match.sport != "table_tennis")
    throw std::invalid_argument("the scripted racket policy plays tennis and table tennis, not " +
                                match.sport);
  const ObservationLayout& l = match.observation;
  blocks_ = {l.offset("ball_position"),  l.offset("ball_velocity"), l.offset("target"),
             l.offset("court_position"), l.offset("court_heading"), l.offset("rally")};
  table_ = match.sport == "table_tennis";
  control_dt_ = match.control_dt;
  legs_.reset();
}

void ScriptedRacketPolicy::act(std::span<const float> o, std::span<float> a) {
  if (control_dt_ <= 0) throw std::logic_error("ScriptedRacketPolicy: act() before start()");
  if (a.size() != kActions)
    throw std::invalid_argument("the scripted racket policy drives the SMPL humanoid (69 actions)");
  std::fill(a.begin(), a.end(), 0.0f);

  const Blocks& at = blocks_;
  const double surface_z = o[at.target + 2];  // the court or table height, root-relative
  const SportPlay play = table_ ? table_play() : tennis_play();
  if (!legs_) legs_.emplace(play.legs, control_dt_);

  // The heading relative to facing the net; `facing` turns heading-frame vectors to the net.
  const double heading = std::atan2(o[at.court_heading + 1], o[at.court_heading]);
  const Eigen::Matrix3d facing = Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()).matrix();
  const Crossing crossing = predict_crossing(o, at, play, surface_z, facing);
  const bool coming = o[at.rally + 1] > 0.5 && crossing.found;  // rally[1]: coming to my team

  // Legs: under the crossing point while the ball comes; otherwise back to the middle.
  Eigen::Vector3d walk_to(0, 0, 0);  // net-facing frame
  if (coming)
    walk_to.y() = crossing.point.y() - play.reach.y();
  else if (const double court_y = o[at.court_position + 1]; std::abs(court_y) > 0.5)
    walk_to.y() = -court_y;
  legs_->act(o, (facing.transpose() * walk_to).head<2>(), -heading, a);

  const Eigen::Vector3d shoulder = body_position(o, kRShoulder);
  const Eigen::Vector3d rest(play.plane, shoulder.y() - 0.6, shoulder.z());
  if (crossing.found && (!legs_->stepping() || crossing.seconds < kReachEarly_s))
    reach(o, facing.transpose() * crossing.point, std::clamp(crossing.seconds / 0.4, 0.0, 1.0), a);
  else
    reach(o, rest, 1.0, a);
}

}  // namespace olympics::client
