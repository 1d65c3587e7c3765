#include "scripted_hurdles.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "smpl_observation.h"

namespace olympics::client {
namespace {

using namespace smpl;

// Tuned on seeds 1-60 (official 110 m; docs/athletics.md has the figures, on other seeds).
//
// Why it walks through a hurdle instead of pushing it from standing: an official hurdle only
// overturns past ~67 deg (its counterweights' centre of mass is 0.41 m behind the pivot), when
// its bar is ~1 m ahead of where it stood, far beyond arms' reach from a standing athlete; a fast
// strike makes it slide along the ground instead of tipping (the impulse beats the friction at
// its base). Walking slowly with the hands on the bar, pushing along the arc the bar falls on,
// tips it steadily; the walker's own legs take it the last few degrees.
constexpr double kStep_s = 0.2;       // a quick step: at 0.25-0.3 s it left its lane sooner
constexpr double kMaxSpeed = 1.0;     // m/s toward the target
constexpr double kAhead_m = 0.8;      // between hurdles: toward the centre line this far ahead
constexpr double kApproach_m = 2.0;   // within this of a standing bar, it walks slowly...
constexpr double kPushAhead_m = 0.3;  // ...toward the centre line at most this far ahead
constexpr double kPastBar_m = 0.5;    // and at most this far past the bar
constexpr double kHandsOn_m = 0.8;    // its hands go on a bar this close
constexpr double kStanding = 0.35;    // a bar above this share of its height is still to push
constexpr double kLetGo = 0.45;       // below this share it stops pushing and walking...
constexpr double kFallen_m = 0.12;    // ...until the bar is this low (lying)
constexpr double kKeepBack_m = 0.8;   // a falling bar: stay this far behind where it will land
constexpr double kLift_m = 0.14;      // swing foot clearance
constexpr double kBarLift_m = 0.35;   // while a bar falls, or lies within kBarNear of the root
constexpr double kLowBar_m = 0.3;     // a bar lower than this lies on the ground
constexpr double kBarBehind_m = -0.3, kBarNear_m = 0.8;
constexpr double kHandBelow_m = 0.03;    // the palms this far below the bar's top edge...
constexpr double kHandThrough_m = 0.05;  // ...and this far along its arc past it
constexpr double kHandsApart_m = 0.18;   // each hand this far to its side of the lane's centre
constexpr double kPalm_m = 0.08;         // the palm's reach past the wrist
constexpr double kCarryDown = -0.35;     // carried arms: forward, this much down (a direction)
constexpr double kCarryOut = 0.1;        // and this much out
constexpr double kRaiseRate = 0.6, kCarryRate = 2.0, kPushRate = 6.0;  // rad/s

}  // namespace

void ScriptedHurdlesPolicy::start(const MatchInfo& match) {
  if (match.sport != "hurdles")
    throw std::invalid_argument("the scripted hurdles policy runs the hurdles, not " + match.sport);
  goal_ = match.observation.offset("goal", "position");
  first_ = match.observation.offset("hurdles", "hurdle_0");
  control_dt_ = match.control_dt;
  StepGains gains;
  gains.step_s = kStep_s;
  gains.max_speed = kMaxSpeed;
  legs_.emplace(gains, control_dt_);
  left_.emplace(Arm::Left);
  right_.emplace(Arm::Right);
  tick_ = 0;
  bar_height_ = upper_arm_ = forearm_ = push_s_ = 0;
}

void ScriptedHurdlesPolicy::carry_arms(std::span<const float> o, std::span<float> a,
                                       const Eigen::Vector3d& forward) {
  const Eigen::Vector3d out(-forward.y(), forward.x(), 0);  // to the left
  const double rate = raising() ? kRaiseRate : kCarryRate;
  for (Arm arm : {Arm::Left, Arm::Right}) {
    const double side = arm == Arm::Right ? -1 : 1;
    ArmDirection& direction = arm == Arm::Right ? *right_ : *left_;
    const Eigen::Vector3d wanted =
        forward + Eigen::Vector3d(0, 0, kCarryDown) + out * side * kCarryOut;
    point_arm(o, a, arm, direction.follow(wanted, rate, control_dt_));
    bend_elbow(a, arm, 0.05);
  }
}

void ScriptedHurdlesPolicy::push_bar(std::span<const float> o, std::span<float> a,
                                     const Eigen::Vector3d& bar, const Eigen::Vector3d& forward) {
  // The bar tips about the bases' front edge: at tilt t its plane's up is (sin t, cos t) and it
  // moves along (cos t, -sin t) (forward, up). The palms go just below its top edge, a little
  // along that arc past it.
  const Eigen::Vector3d out(-forward.y(), forward.x(), 0);
  const double c = std::clamp((bar.z() + root_height(o)) / bar_height_, 0.0, 1.0);
  const double s = std::sqrt(1 - c * c);
  const Eigen::Vector3d up = s * forward + c * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d along_arc = c * forward - s * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d palms =
      bar - kHandBelow_m * up + std::min(kHandThrough_m, push_s_) * along_arc;
  for (Arm arm : {Arm::Left, Arm::Right}) {
    const double side = arm == Arm::Right ? -1 : 1;
    const Eigen::Vector3d shoulder = body_position(o, arm == Arm::Right ? kRShoulder : kLShoulder);
    // Two links: the upper arm turned down from the line to the hand by the angle the elbow
    // needs, the elbow folding up (rolled a quarter turn, as a boxer's guard).
    Eigen::Vector3d to_hand = palms + out * side * kHandsApart_m - shoulder;
    const double l1 = upper_arm_, l2 = forearm_;
    const double r = std::clamp(to_hand.norm(), 0.05, l1 + l2 - 1e-3);
    to_hand.normalize();
    const double lift =
        std::acos(std::clamp((l1 * l1 + r * r - l2 * l2) / (2 * l1 * r), -1.0, 1.0));
    const double bend =
        M_PI - std::acos(std::clamp((l1 * l1 + l2 * l2 - r * r) / (2 * l1 * l2), -1.0, 1.0));
    Eigen::Vector3d down = Eigen::Vector3d::UnitZ() - to_hand.z() * to_hand;
    down = down.norm() > 1e-6 ? Eigen::Vector3d(down.normalized()) : forward;
    const Eigen::Vector3d upper = std::cos(lift) * to_hand - std::sin(lift) * down;
    ArmDirection& direction = arm == Arm::Right ? *right_ : *left_;
    point_arm(o, a, arm, direction.follow(upper, raising() ? kRaiseRate : kPushRate, control_dt_),
              arm == Arm::Right ? M_PI / 2 : -M_PI / 2);
    bend_elbow(a, arm, bend);
  }
}

void ScriptedHurdlesPolicy::act(std::span<const float> o, std::span<float> a) {
  if (!legs_) throw std::logic_error("ScriptedHurdlesPolicy: act() before start()");
  std::fill(a.begin(), a.end(), 0.0f);
  ++tick_;
  const double root_z = root_height(o);
  auto bar = [&](int i) {  // hurdle i's top bar (heading frame, from the root)
    return Eigen::Vector3d(o[first_ + 3 * i], o[first_ + 3 * i + 1], o[first_ + 3 * i + 2]);
  };
  auto bar_z = [&](int i) { return bar(i).z() + root_z; };  // above the ground
  if (bar_height_ == 0) {
    bar_height_ = bar_z(0);
    upper_arm_ = (body_position(o, kRElbow) - body_position(o, kRShoulder)).norm();
    forearm_ = (body_position(o, kRHand) - body_position(o, kRElbow)).norm() + kPalm_m;
  }
  // The lane's centre line runs through the goal and every hurdle's bar where it stands: take
  // the farthest one still standing (fallen bars lie a metre on).
  const Eigen::Vector2d goal(o[goal_], o[goal_ + 1]);
  Eigen::Vector2d along = goal.normalized();
  for (int i = 9; i >= 0; --i)
    if (bar_z(i) > 0.8 * bar_height_ && (goal - bar(i).head<2>()).norm() > 3) {
      along = (goal - bar(i).head<2>()).normalized();
      break;
    }
  const double to_goal = goal.dot(along);
  auto on_line = [&](double ahead) -> Eigen::Vector2d { return goal - along * (to_goal - ahead); };
  auto ahead_of_me = [&](int i) { return bar(i).head<2>().dot(along); };

  // The next hurdle still to push over, and how far ahead its bar is.
  int next = -1;
  for (int i = 0; i < 10 && next < 0; ++i)
    if (bar_z(i) > kStanding * bar_height_ && ahead_of_me(i) > -0.3) next = i;
  const double d = next >= 0 ? ahead_of_me(next) : 1e9;

  Eigen::Vector2d target = on_line(kAhead_m);
  bool pushing = false;
  if (next >= 0 && d < kApproach_m) {
    const bool let_go = bar_z(next) < kLetGo * bar_height_;
    target = on_line(let_go ? 0.0 : std::min(d + kPastBar_m, kPushAhead_m));
    pushing = d < kHandsOn_m && !let_go;
  }
  push_s_ = pushing ? push_s_ + control_dt_ : 0;
  bool falling = false;
  // A hurdle falling (past its tipping angle, not down yet): keep back from where its bar will
  // land (its pivot, then its height on), so the bar does not come down on a foot.
  for (int i = 0; i < 10; ++i) {
    const double h = bar_z(i);
    if (h > kStanding * bar_height_ || h < kFallen_m) continue;
    const double lands =
        ahead_of_me(i) - std::sqrt(std::max(0.0, bar_height_ * bar_height_ - h * h)) + bar_height_;
    if (lands > -0.5) {
      target = on_line(std::clamp(lands - kKeepBack_m, -kPushAhead_m, kPushAhead_m));
      falling = true;
    }
  }
  // High steps while a bar falls or lies just ahead: a foot under a landing bar, or one that
  // scuffs a lying one, trips the walker out of its lane. Hurdles knocked a race on seeds 1-40:
  // 0.18 m over lying bars only 2.7, 0.25 m 2.9; 0.35 m over falling bars too 4.9 (7 of 40
  // finish), 0.3 m 4.5, 0.45 m 3.8.
  bool high_step = falling;
  for (int i = 0; i < 10; ++i)
    if (bar_z(i) < kLowBar_m && ahead_of_me(i) > kBarBehind_m && ahead_of_me(i) < kBarNear_m)
      high_step = true;
  legs_->set_lift(high_step ? kBarLift_m : kLift_m);
  legs_->act(o, target, std::atan2(along.y(), along.x()), a);

  const Eigen::Vector3d forward(along.x(), along.y(), 0);
  if (pushing)
    push_bar(o, a, bar(next), forward);
  else
    carry_arms(o, a, forward);
}

std::unique_ptr<Policy> make_scripted_hurdles() {
  return std::make_unique<ScriptedHurdlesPolicy>();
}

}  // namespace olympics::client
