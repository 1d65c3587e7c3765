// A scripted stepping controller for the SMPL humanoid: it walks the root toward a point on the
// ground, from the self observation alone (358 floats, heading frame of the root).
//
// Why this design: actions are PD targets, not torques, so the controller is written as leg
// inverse kinematics. Each step one leg stands and the other swings, alternately, every
// `step_s` seconds:
// - the stance leg is solved in the upright heading frame (not the pelvis's tilted one), so its
//   stiff hip drive pulls the pelvis and torso upright over the planted foot, and its length
//   sets the pelvis height;
// - the swing foot is lifted and placed where the centre of mass will need it (a Raibert-style
//   rule: half a step of the current velocity ahead, plus a gain on the velocity error against
//   the desired velocity toward the target), which both balances and moves the body;
// - both feet are kept flat on the ground by their ankles.
// Close to the target and slow, it stands with both feet down and an ankle/hip strategy.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>

namespace olympics::client {

// Standing balance: ankle and hip pitch/roll from where the root is over the ankles and how it
// moves (rad per m, rad per m/s, rad).
struct BalanceGains {
  double ankle_p = 1.0, ankle_d = 2.0, ankle_bias = 0.0, hip_p = 1.0;
};

struct StepGains {
  BalanceGains balance;
  double step_s = 0.3;           // duration of one step
  double max_speed = 1.2;        // m/s toward the target
  double max_side_speed = 0.55;  // m/s sideways
  double speed_per_m = 2.4;      // desired speed per metre of distance to the target
  double lead_s = 0.14;          // foot placed ahead by the velocity times this (half a step)
  double velocity_gain = 0.13;   // foot placement per m/s of velocity error
  double stance_width = 0.14;    // swing foot this far to its side of the centre of mass
  double max_step = 0.5;         // swing foot at most this far from the stance foot, m
  double lift = 0.14;            // swing foot clearance, m
  double leg_length = 0.77;      // stance hip-to-ankle distance (a slightly bent knee)
  double upright_gain = 4.3;     // stance hip correction per radian of pelvis tilt
  double turn_gain = 3.0;        // stance hip twist per radian of heading error
  double start_m = 0.3;          // standing, it starts to step when the target is this far
  double arrive_m = 0.12;        // closer than this and slower than...
  double settle_speed = 0.25;    // ...this, it stands still
  // Standing, it also steps (in place) to turn when asked to turn more than this; it stands
  // again once the turn left is under half of it. 0: it turns only while walking somewhere.
  double turn_start = 0;
  // Balancing the centre of mass (balance_centre_of_mass), it steps to catch itself when that
  // point is this far from the middle of the feet, or the body moves this fast; 0: never.
  double recover_m = 0.12, recover_speed = 0.35;
  // Speed limits per axis and the side-step shuffle (the lead foot steps out, the trail foot
  // closes beside the stance foot). The defaults keep the plain gait; side_stepping() below
  // sets them for a player that must cover ground sideways.
  double max_forward_speed = 0;  // m/s forward and back on its own (0: only max_speed limits)
  double max_side_step = 0;      // a step's sideways reach, m (0: max_step, as forward)
  // The lead foot (the one on the side moved toward) lands this much further out per m/s asked
  // sideways, s; negative: nearer the body, which keeps it accelerating that way.
  double side_step = 0;
  // How far toward the whole body's centre of mass (0: the root, 1: the centre of mass) the
  // swing foot's placement is reckoned from; the centre of mass's offset from the root is
  // averaged over about a step, which smooths out the swinging leg's own weight. A body whose
  // arms are held out in front (a boxer's guard puts the centre of mass 4 cm ahead of the root)
  // otherwise keeps falling forward onto each step: stepping in place on a spot, the guard up,
  // it drifted 0.15 m/s forward while asked back at 0.3 m/s; about the centre of mass, under
  // 0.01 m/s (docs/combat-sports.md). 0 by default: the other sports were tuned about the root.
  double centre_of_mass_placement = 0;
  // The catch step: standing, balancing the centre of mass, and knocked off balance (recover_m,
  // recover_speed), the first step lasts this long (s) and puts the swing foot, to its side,
  // where the capture point will be when it lands (the centre of mass plus the velocity times
  // the rest of the step and sqrt(height / g), where the body would come to rest over the foot),
  // 5 cm beyond it. 0: a plain first step (placed half a step of velocity ahead, 0.3 s long).
  // A planted boxer given 0.4-0.6 m/s sideways or backward fell in 17 of 90 runs with the plain
  // step, in 4 with a 0.2 s catch step on the falling side (tests/sports/catch_step_test.cpp);
  // in bouts it changed nothing measurable, so no sport sets it yet (docs/combat-sports.md).
  double catch_step_s = 0;
  // The catch step by the foot on the side the capture point lies (else by the foot on the
  // target's side): the feet cannot cross, so the other foot cannot catch a sideways fall.
  // In bouts a boxer is mostly knocked toward the side the other boxer stands; that foot then
  // steps toward it and fell in 12 of 92 such starts, the target's foot in none of 72
  // (docs/combat-sports.md, thirteenth round).
  bool catch_on_the_falling_side = false;
};

// A faster sideways gait, `base` otherwise: 0.2 s steps, 0.6 m side steps, the lead foot
// placed nearer the body. Measured (sandbox solo, sent 3-3.7 m): 1.0 m/s sideways once under
// way (0.76 m/s over the first 2.5 s from standing; the plain gait 0.21-0.24), no falls; over
// those 2.5 s forward 0.51 m/s, but backward only 0.08 (plain: 0.61 and 0.47). docs/control.md.
StepGains side_stepping(StepGains base = {});

// The leg pieces the controller is built from, for other leg motions (a kick's standing leg):
// hip and knee angles that put the ankle at `hip_to_ankle` (in the hip's parent frame; the
// heading frame for a leg that should right the pelvis over its foot), and ankle targets that
// turn the foot flat from the shank as it is now.
void write_leg_toward(std::span<float> action, int hip, const Eigen::Vector3d& hip_to_ankle);
void write_flat_foot(std::span<const float> observation, std::span<float> action, int knee);

// The linear inverted pendulum's time constant sqrt(h / g) at the root's height: a body moving at
// v comes to rest over a foot v times this ahead of its centre of mass (the capture point).
double pendulum_time_s(std::span<const float> observation);

class StepController {
 public:
  // `control_dt`: seconds per tick, the match's (MatchInfo::control_dt).
  StepController(const StepGains& gains, double control_dt)
      : gains_(gains), control_dt_(control_dt) {}

  // Writes the leg joints (hips, knees, ankles) of `action` to walk toward `target`, a ground
  // point in the heading frame relative to the root, turning by `turn` radians (left positive)
  // while stepping. Other joints are left as they are.
  void act(std::span<const float> observation, const Eigen::Vector2d& target, double turn,
           std::span<float> action);

  bool stepping() const { return stepping_; }
  // How long the step under way has run, this tick's act() included (s).
  double step_time_s() const { return phase_s_; }

  // Standing, the next act() steps toward a target as near as `arrive_m` (where a walk stops),
  // not only beyond `start_m`, and the first step is the foot away from the target's side (the
  // trailing foot). For legs started afresh where a body was put back standing, away from where
  // it is sent (a racket match's marks at each point's start).
  void step_at_once_trailing_foot_first() { step_at_once_ = true; }

  // The swing foot's clearance from the next step on (stepping over something low).
  void set_lift(double metres) { gains_.lift = metres; }

  // Standing, balance the whole body's centre of mass instead of the root: `offset` is where it
  // is (heading frame, from the root; control::BodyModel::centre_of_mass), held `ahead` metres in
  // front of the ankles. For players whose arms carry weight out in front (a racket).
  void balance_centre_of_mass(const Eigen::Vector3d& offset, double ahead) {
    com_offset_ = offset.head<2>() - Eigen::Vector2d(ahead, 0);
    balance_com_ = true;
  }

  // The whole body's centre of mass this tick (heading frame, from the root;
  // control::BodyModel::centre_of_mass), where StepGains::centre_of_mass_placement reckons the
  // swing foot's placement from: given before every act() when that share is above 0 (the caller
  // has the body's model; SMPL and SMPL-X alike).
  void set_centre_of_mass(const Eigen::Vector3d& offset) { com_ = offset.head<2>(); }

 private:
  void stand(std::span<const float> o, std::span<float> a) const;
  void begin_step(std::span<const float> o, bool left_swings);
  Eigen::Vector2d capture_point(std::span<const float> o, double in_s) const;
  bool losing_balance(std::span<const float> o) const;
  Eigen::Vector2d placement_origin();

  StepGains gains_;
  double control_dt_;
  bool stepping_ = false;
  bool left_swings_ = true;
  bool catching_ = false;      // this step is the catch step (StepGains::catch_step_s)
  bool step_at_once_ = false;  // step_at_once_trailing_foot_first(), for the next act()
  double phase_s_ = 0;         // time into the current step
  Eigen::Vector2d lift_off_{0, 0};
  bool balance_com_ = false;
  Eigen::Vector2d com_offset_{0, 0};  // the point balanced over the ankles, from the root
  // centre_of_mass_placement: the centre of mass from the root this tick (set_centre_of_mass),
  // and averaged over about a step.
  std::optional<Eigen::Vector2d> com_, step_com_;
};

}  // namespace olympics::client
