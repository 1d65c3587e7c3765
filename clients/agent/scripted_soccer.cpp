#include "scripted_soccer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "smpl_observation.h"

namespace olympics::client {
namespace {

using namespace smpl;

constexpr double kBehind_m = 0.7;      // the approach point, behind the ball
constexpr double kLinedUp_m = 0.35;    // off the ball-to-goal line by less than this: lined up
constexpr double kLoseLine_m = 0.6;    // ...and it stops pushing when further off than this
constexpr double kThrough_m = 0.6;     // while pushing, it walks to this far past the ball
constexpr double kKeepBack_m = 3.8;    // from the ball while the other side restarts
constexpr double kDefend_m = 5.0;      // the second player, this far out from its own goal
constexpr double kDownBelow_m = -0.4;  // a teammate's root this far below mine: it is down

Eigen::Vector2d xy(std::span<const float> o, int at) { return {o[at], o[at + 1]}; }

double bearing(const Eigen::Vector2d& v) { return std::atan2(v.y(), v.x()); }

}  // namespace

void ScriptedSoccerPolicy::start(const MatchInfo& match) {
  if (match.sport != "soccer")
    throw std::invalid_argument("the scripted soccer policy plays soccer, not " + match.sport);
  const ObservationLayout& l = match.observation;
  blocks_ = {l.offset("ball", "position"), l.offset("goals", "attack"), l.offset("goals", "defend"),
             l.has("teammates") ? l.offset("teammates", "position_0") : -1,
             l.offset("match", "restart")};
  StepGains gains;
  gains.turn_start = 0.5;
  legs_.emplace(gains, match.control_dt);
  lined_up_ = false;
}

void ScriptedSoccerPolicy::act(std::span<const float> o, std::span<float> a) {
  if (!legs_) throw std::logic_error("ScriptedSoccerPolicy: act() before start()");
  if (a.size() != kActions)
    throw std::invalid_argument("the scripted soccer policy drives the SMPL humanoid (69 actions)");
  std::fill(a.begin(), a.end(), 0.0f);
  const Blocks& at = blocks_;
  const Eigen::Vector2d ball = xy(o, at.ball), goal = xy(o, at.goal), own_goal = xy(o, at.own_goal);
  const bool theirs_to_take = o[at.restart] < -0.5;

  if (theirs_to_take) {
    lined_up_ = false;
    const Eigen::Vector2d back = ball + (own_goal - ball).normalized() * kKeepBack_m;
    return legs_->act(o, back, bearing(ball), a);
  }
  // One chaser per side: whoever is nearer the ball (each of the two sees the same distances),
  // unless the teammate is down (its root far below mine).
  const bool mate_down = at.mate >= 0 && vec3(o, at.mate).z() < kDownBelow_m;
  const bool chaser = at.mate < 0 || mate_down || ball.norm() < (ball - xy(o, at.mate)).norm();
  if (!chaser) {
    lined_up_ = false;
    const Eigen::Vector2d to_ball = ball - own_goal;
    const Eigen::Vector2d guard =
        own_goal + to_ball.normalized() * std::min(kDefend_m, 0.5 * to_ball.norm());
    return legs_->act(o, guard, bearing(ball), a);
  }

  // Where I stand against the line from the ball to the goal: `along` < 0 behind the ball.
  const Eigen::Vector2d dir = (goal - ball).normalized();
  const Eigen::Vector2d me = -ball;  // my root, relative to the ball
  const double along = me.dot(dir);
  const double off_line = std::abs(dir.x() * me.y() - dir.y() * me.x());
  if (lined_up_)
    lined_up_ = along < 0.1 && off_line < kLoseLine_m;
  else
    lined_up_ = along < -0.2 && along > -kBehind_m - 0.4 && off_line < kLinedUp_m;
  if (lined_up_) return legs_->act(o, ball + dir * kThrough_m, bearing(dir), a);

  Eigen::Vector2d target = ball - dir * kBehind_m;
  if (along > -0.3 && off_line < 0.9) {
    // On the wrong side of the ball, or too close beside it: round it, on my side of the line.
    const Eigen::Vector2d perp(-dir.y(), dir.x());
    const double side = perp.dot(me) >= 0 ? 1 : -1;
    target = ball - dir * (kBehind_m + 0.3) + perp * side * 1.0;
  }
  legs_->act(o, target, bearing(target.norm() > 1.0 ? target : dir), a);
}

std::unique_ptr<Policy> make_scripted_soccer() { return std::make_unique<ScriptedSoccerPolicy>(); }

}  // namespace olympics::client
