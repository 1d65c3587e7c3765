#include "scripted_golf.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "golf/golf_club.h"
#include "smpl_observation.h"

namespace olympics::client {
namespace {

using namespace smpl;

// The putter arm's direction (heading frame) at `angle` forward of the bottom of a pendulum
// whose plane leans `out` radians out to the right of the vertical (clear of the right leg).
// The swing's line turns `aim` radians left of straight ahead (the face meets the ball a little
// open: aimed straight, putts start to the right).
Eigen::Vector3d pendulum(double angle, double out, double aim) {
  const double ahead = std::sin(angle), side = -std::sin(out) * std::cos(angle);
  return {ahead * std::cos(aim) - side * std::sin(aim),
          ahead * std::sin(aim) + side * std::cos(aim), -std::cos(out) * std::cos(angle)};
}

}  // namespace

void ScriptedGolfPolicy::start(const MatchInfo& match) {
  if (match.sport != "golf")
    throw std::invalid_argument("the scripted golf policy plays golf, not " + match.sport);
  const ObservationLayout& l = match.observation;
  at_ = {l.offset("ball", "position"), l.offset("club_head", "position"),
         l.offset("target", "position"), l.offset("play", "contact")};
  control_dt_ = match.control_dt;
  legs_.emplace(StepGains{}, control_dt_);
  const sports::equipment::EquipmentSpec putter =
      sports::golf::club_equipment(sports::golf::putter());
  model_.emplace(control::BodyModel::humanoid(core::HumanoidKind::Smpl, &putter));
  arm_ = ArmDirection(Arm::Right);
  phase_ = Phase::Lower;
  phase_s_ = 0;
  was_struck_ = false;
}

void ScriptedGolfPolicy::act(std::span<const float> o, std::span<float> a) {
  if (!legs_) throw std::logic_error("ScriptedGolfPolicy: act() before start()");
  if (a.size() != kActions)
    throw std::invalid_argument("the scripted golf policy drives the SMPL humanoid (69 actions)");
  std::fill(a.begin(), a.end(), 0.0f);
  const Eigen::Vector3d ball = vec3(o, at_.ball), head = vec3(o, at_.head);
  const Eigen::Vector3d hole = vec3(o, at_.target);
  const bool struck = o[at_.contact] > 0.5;
  // The stroke is over (the ball at rest: the referee addresses the athlete anew): start over.
  if (was_struck_ && !struck) phase_ = Phase::Lower, phase_s_ = 0, arm_ = ArmDirection(Arm::Right);
  was_struck_ = struck;
  phase_s_ += control_dt_;
  if (gains_.balance_centre_of_mass)
    legs_->balance_centre_of_mass(model_->centre_of_mass(model_->pose_from_observation(o)),
                                  gains_.balance_ahead);
  legs_->act(o, Eigen::Vector2d::Zero(), 0.0, a);

  const Eigen::Vector3d shoulder = body_position(o, kRShoulder);
  const double reach = (head - shoulder).norm();
  Eigen::Vector3d direction;
  switch (phase_) {
    case Phase::Lower:
      direction = arm_.follow(pendulum(-gains_.backswing, gains_.out, gains_.aim),
                              gains_.lower_rate, control_dt_);
      if (phase_s_ > gains_.settle_s) {
        // The ball's speed to roll the distance and arrive at arrive_speed; the head's for it.
        const double d = (hole - ball).head<2>().norm();
        const double v =
            std::sqrt(gains_.arrive_speed * gains_.arrive_speed + 2 * gains_.decel * d);
        rate_ = v / gains_.ball_per_head / std::max(reach, 0.5);
        phase_ = Phase::Swing;
        phase_s_ = 0;
      }
      break;
    case Phase::Swing:
      direction = arm_.follow(pendulum(gains_.follow, gains_.out, gains_.aim), rate_, control_dt_);
      if (phase_s_ > 1.5) phase_ = Phase::Done, phase_s_ = 0;
      break;
    case Phase::Done:
      direction = arm_.follow(pendulum(gains_.follow, gains_.out, gains_.aim), 0.0, control_dt_);
      break;
  }
  point_arm(o, a, Arm::Right, direction);
  bend_elbow(a, Arm::Right, 0);
}

std::unique_ptr<Policy> make_scripted_golf() { return std::make_unique<ScriptedGolfPolicy>(); }

}  // namespace olympics::client
