// A standing kick for the scripted soccer player, on the control toolkit (docs/control.md): the
// ball at rest, the player standing near it, the kick sends it along a direction at a planned
// speed while the other leg keeps the body up.
//
// How (a coach's instep drive, toe first, since the SMPL foot is a box):
//  1. shift the weight onto the kicking foot's side;
//  2. plant the other foot beside the ball (a step, the kicking leg standing);
//  3. shift the weight onto the planted foot;
//  4. draw the kicking foot back and swing it by inverse kinematics through the ball along the
//     direction at the speed the ball needs (gravity-compensated, velocity fed forward);
//  5. put it down beside the planted foot and stand on both again.
// Standing legs are solved in the upright heading frame (their drives right the pelvis over the
// feet) for where the pelvis should go to bring the centre of mass over the support, and carry
// their share of the body's weight (gravity compensation).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>

#include "control/body_model.h"
#include "control/limb_control.h"
#include "step_controller.h"

namespace olympics::client {

// Tunable constants of the kick (chosen on penalty tuning seeds 1-60, never on the benchmark's).
struct KickGains {
  double shift_s = 0.3;    // a weight shift from one foot to the other
  double plant_s = 0.35;   // the plant step
  double back_s = 0.12;    // drawing the kicking foot back
  double land_s = 0.35;    // from the follow-through to the foot down
  double settle_s = 0.35;  // standing on both feet again
  // The kick starts with the root this far behind the ball: from 0.35 m the plant step's weight
  // shift knocked the ball early in 22 of 100 kicks (seeds 1-100); 0.5 on seeds 1-200.
  double approach_behind_m = 0.5;
  double approach_side_m = 0.0;  // ...and this far to the planted foot's side of it
  double plant_lift_m = 0.1;     // the plant step's foot clearance
  double plant_side_m = 0.27;    // the planted ankle this far beside the ball's centre
  double plant_reach_m = 0.05;   // ...at most this far ahead of the centre of mass
  double plant_behind_m = 0.1;   // ...and this far behind it
  double backswing_m = 0.25;     // the foot drawn back this far behind the contact point
  double backswing_up_m = 0.15;
  double backswing_out_m = 0.0;  // ...and this far out to the kicking foot's side
  double follow_m = 0.3;         // the follow-through, past the contact point
  double follow_up_m = 0.12;
  // The foot swung at the ball's planned speed over this (a ball speed per foot speed at contact):
  // 2.4 (seeds 1-60) left 58 of 200 penalties short of the line (penalty seeds 1-200, most struck
  // at about half the plan, the kicker down); 2.0 swings a fifth faster (issue 30's fifth round,
  // the swing's line turned 4 degrees left of the aim, ScriptedSoccerPolicy turns it 5: goals 134
  // of 200 against 124 at 2.4 and 128 at 1.8; against the keeper 96, 87, 79).
  double ball_per_foot = 2.0;
  double max_foot_speed = 7;    // m/s
  double com_gain = 0.6;        // pelvis moved per m of centre-of-mass error, per tick
  double com_damping_s = 0.15;  // ...less the velocity times this
  double max_shift_m = 0.08;    // per tick
  double ankle_p = 3.0;         // standing ankle rad per m of centre-of-mass error
  double ankle_d = 0.5;         // ...per m/s of the body's velocity
  bool rigid_ankles = true;     // standing ankles flat for the legs as asked, not as they are
  double upright_gain = 4.3;    // standing hip correction per radian of pelvis tilt
  // Gravity compensation of standing legs, multiples of the weight: 0, since with 1-2 the kicker
  // fell more and struck fewer balls (tuning seeds 1-60).
  double support_scale = 0.0;
  double swing_scale = 1.5;  // ...of the swinging leg
  // The weight shift onto the planted foot goes on until the centre of mass is this near the
  // planted ankle sideways, at most this much longer (penalty seeds 1-200: the kicker still up
  // 2 s after 2 of 200 kicks before, with the catch below 53, with both 109).
  double planted_within_m = 0.23;
  double planted_wait_s = 0.3;
  // After the follow-through the kick catches the body with steps of its own stepping controller
  // for up to catch_s (0: the caller's stepping controller takes over at once, as before issue
  // 30's fourth round, or with step_after false the kick puts the foot down itself): steps this
  // quick and this long (the walk's 0.3 s and 0.5 m: 1 in 200 up).
  double catch_s = 2.0;
  double catch_step_s = 0.23;
  double catch_max_step_m = 1.0;
  bool step_after = true;
  double ask_ahead_s = 0.02;  // the swing asked for this long after the tick starts
};

class SoccerKick {
 public:
  SoccerKick(const control::BodyModel& model, double control_dt, KickGains gains = {});

  // Starts a kick with the right foot (or the left) of a ball at rest.
  void start(bool right_foot);
  bool active() const { return phase_ != Phase::Idle; }
  bool struck() const { return struck_; }
  bool right_foot() const { return right_; }
  // The phase under way, by name ("idle", "shift_to_kicker", "plant", ...): for tracing.
  const char* phase_name() const;
  // Where the root should stand, relative to the ball, to start a kick along `direction`.
  Eigen::Vector2d approach_from_ball(const Eigen::Vector2d& direction, bool right_foot) const;

  // One tick: `ball` (heading frame, from the root), the kick's `direction` (heading frame,
  // horizontal unit) and the ball's wanted speed. Writes every leg joint and the trunk's.
  void act(std::span<const float> observation, const control::BodyPose& pose,
           const Eigen::Vector3d& ball, const Eigen::Vector2d& direction, double ball_speed,
           std::span<float> action);
  // Gives up a kick under way (the ball moved away, the player was pushed).
  void abort() { phase_ = Phase::Idle; }

 private:
  enum class Phase { Idle, ShiftToKicker, Plant, ShiftToPlanted, Back, Swing, Land, Settle, Catch };
  void next(Phase p) { phase_ = p, t_ = 0; }
  // Standing legs: each `share` of the weight (negative: swinging, not written), the centre of mass
  // led to `com_target` (heading frame, horizontal).
  void support(std::span<const float> o, const control::BodyPose& pose,
               const Eigen::Vector2d& com_target, double left_share, double right_share,
               std::span<float> a);
  void swing(const control::BodyPose& pose, bool left, const Eigen::Vector3d& now,
             const Eigen::Vector3d& then, const Eigen::Vector3d& toward, std::span<float> a);

  const control::BodyModel& model_;
  double dt_;
  KickGains g_;
  control::LimbControl swinging_[2];
  Phase phase_ = Phase::Idle;
  double t_ = 0;
  bool right_ = true, struck_ = false;
  Eigen::Vector3d lift_off_{0, 0, 0};   // where the swinging toe left the ground
  Eigen::Vector3d plant_{0, 0, 0};      // where the planted ankle is to go (from the ball)
  Eigen::Vector3d swing_end_{0, 0, 0};  // where the follow-through ended
  double swing_speed_ = 0;
  std::optional<StepController> catching_;  // the steps after the kick (Phase::Catch)
};

}  // namespace olympics::client
