// A fencing guard and its footwork for the SMPL humanoid, from the self observation alone: the
// feet staggered along the line of attack (the front foot ahead, the weight toward the back
// foot), kept by steps that move one foot at a time (an advance: front foot, then back foot; a
// retreat: back foot, then front foot), and a lunge from that guard (the back leg straightens
// while the front foot flies ahead and lands with its knee bent), recovered back to guard.
//
// Why its own controller and not StepController: the stepping gait's feet stand side by side
// and which foot is behind depends on the step's phase, so a lunge could only be taken over in
// the middle of a step, and fell (docs/combat-sports.md, "Issue 30, third round").
//
// Every move runs to its end before the next is taken: `act` returns whether it is free.
#pragma once

#include <Eigen/Core>
#include <span>

namespace olympics::client::control {

struct GuardGains {
  double front_m = 0.18, back_m = 0.18;  // guard: ankles ahead of and behind the balance point
  double width_m = 0.20;                 // guard: ankles this far apart sideways
  double leg_m = 0.74;                   // hip-to-ankle in guard (knees bent)
  double step_m = 0.12;                  // one advance or retreat
  double step_s = 0.22;                  // one foot's flight
  double settle_s = 0.08;                // both feet down between the two feet's steps
  double lift_m = 0.14;
  double shift_s = 0.4;  // weight onto the foot that stays, before the other one leaves
  double guard_share = 0.4, loaded_share = 0.8;  // balance point from the back foot to the front
  double lunge_m = 0.35;                         // how far the front foot flies
  double lunge_s = 0.2;                          // its flight
  double lunge_hold_s = 0.25;                    // landed, before recovering
  double recover_s = 0.3;                        // the front foot back to guard
  double back_leg_lunge_m = 0.77;                // the back leg straightened in the lunge
  double front_leg_lunge_m = 0.68;               // the front knee bent over the landed foot
  double back_push_m = 0.08;            // the back leg's target puts the hip this far further ahead
  double upright_gain = 4.3;            // hip correction per radian of pelvis tilt
  double ankle_p = 3.0, ankle_d = 2.0;  // guard balance over the feet (rad per m, per m/s)
  double turn_gain = 1.0;               // hip twist per radian of heading error
  double catch_s = 0.3;
  double step_speed = 0.25;  // m/s the body moves at in an advance or retreat
  // the flying foot lands further sideways by the body's velocity times this
};

class GuardFootwork {
 public:
  enum class Move { Guard, Advance, Retreat, Lunge };
  // Where a move is: for the fencer's tactics and for counting where touches came from.
  enum class Stage { Guard, Shift, FirstFoot, Settle, SecondFoot, Lunging, Lunged, Recovering };

  GuardFootwork(const GuardGains& gains, double control_dt) : g_(gains), dt_(control_dt) {}

  // Writes the leg joints of `action`: goes on with the current move, or starts `wanted` when
  // none is under way. `turn`: heading error (rad, left positive); `side_m`: how far to place
  // the feet to the left of where the guard puts them (keeping to the piste's middle).
  void act(std::span<const float> observation, Move wanted, double turn, double side_m,
           std::span<float> action);

  Stage stage() const { return stage_; }
  Move move() const { return move_; }
  bool free() const { return stage_ == Stage::Guard; }
  // True while the feet are not (yet) staggered as the guard wants: the fencer then forms it.
  bool out_of_guard(std::span<const float> observation) const;
  double stage_s() const { return stage_s_; }

 private:
  void begin(std::span<const float> o, Move move, double side_m);
  void begin_foot(std::span<const float> o, bool front, Eigen::Vector2d to);
  void stand_guard(std::span<const float> o, double turn, double front_leg, double back_leg,
                   double share, std::span<float> a) const;
  void swing_foot(std::span<const float> o, double s, double lift, double stance_leg, double push,
                  double turn, std::span<float> a) const;

  GuardGains g_;
  double dt_;
  Move move_ = Move::Guard;
  Stage stage_ = Stage::Guard;
  double stage_s_ = 0;
  bool front_flies_ = true;                // which foot is in the air
  Eigen::Vector2d from_{0, 0}, to_{0, 0};  // its lift-off and landing, from the other ankle
  double side_m_ = 0;
};

}  // namespace olympics::client::control
