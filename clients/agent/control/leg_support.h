// Both legs from a planned share of the weight: stand on both feet, carry the body over one, and
// lift the other, from the observation at the control rate (SMPL or SMPL-X legs: bodies 1-3 and
// 5-7 in both). Written for SMPL-X, whose drives (hips and knees 250 N·m/rad, ankles 150, almost
// undamped) are softer than gravity's toppling stiffness on one leg (m g h, about 640 N·m/rad).
//
// Why not the standing balance (standing_balance.h) with its centre of mass moved toward a foot:
// it compensates only the pitch of the weight, half on each leg, so the roll torque a loaded hip
// must hold (the trunk's weight beside that hip) goes uncompensated, and its sideways command
// rolls both hips whatever the load, which on one leg rolls the pelvis instead of carrying it
// (docs/basketball.md, "SMPL-X walking and the falls, second round", and "A weight shift onto
// one leg").
//
// Here the ground's force is planned: `left_share` of the weight under the left foot, the rest
// under the right, and every hip, knee and ankle targets the torque that holds what rests on it,
// in all three axes (gravity on the leg below the joint plus that foot's share of the ground's
// force, about the joint, which acts under the centre of mass: the loaded ankle carries the
// body's lean, so only the feedback below is left to balance it). An unloaded leg holds only its
// own weight, so it can be lifted. The same share sets where the centre of mass is held: the
// share's point between the two feet. Sideways it is carried there by the parallelogram (both
// hips roll by a, both ankles by -a, the trunk and the feet staying level): a from the planned
// displacement plus feedback on the centre of mass's place and velocity. With both feet loaded
// the feedback goes to hips and ankles alike; with one foot loaded only to the ankles, while the
// loaded hip keeps the pelvis level and the free hip hangs its leg at the parallelogram's tilt
// (on one leg a hip that carries the feedback rolls the pelvis over the foot). Forward the centre
// of mass is held over the loaded ankles by their pitch.
#pragma once

#include <array>
#include <span>

#include "control/body_model.h"

namespace olympics::client::control {

// Measured on SMPL-X (tuning seeds 1-20 of a basketball 1v1, docs/basketball.md): side_d above
// about 2.2 with both feet loaded, or below 2 on one foot, fell; hence the two-foot scale.
struct LegSupportGains {
  double forward_p = 600;        // N·m per m of the centre of mass off its place, ankles' pitch
  double forward_d = 120;        // N·m per m/s
  double side_p = 10;            // rad of parallelogram roll per m sideways, on one foot
  double side_d = 2.5;           // rad per m/s of the centre of mass's velocity
  double both_feet_scale = 0.7;  // of the sideways feedback with the weight shared evenly
  double upright = 100;          // N·m per unit of the pelvis's tilt, the loaded hips' pitch
  double stance_level = 1;       // rad of the loaded hip's roll per unit of the pelvis's tilt
  double swing_level = 1;        // and of the free hip's, the other way
  double ahead = 0.03;           // m: the centre of mass held this far ahead of the loaded ankles
  double foot_point = 0.3;       // where on a foot it is held: 0 its ankle, 1 its centre
  double compensation = 1.0;     // scale of the planned loads' torques
  // Below this share of the weight a leg's hip has no yaw stiffness: its yaw target is where the
  // hip is. 0: never (the hip's yaw held at 0, the pelvis's heading). Held, the free leg's hip
  // twists the foot it just put down, and the body with it, turning 0.1-0.3 rad at each step;
  // 10 cm steps fell 2.0 times a minute held, 0.23 free below 0.15 (docs/basketball.md, "Why
  // the body turned").
  double free_hip_yaw_below = 0;
};

struct LegSupport {
  double left_share = 0.5;           // of the weight on the left foot, 0..1
  double left_share_rate = 0;        // its rate, 1/s (the centre of mass's planned velocity)
  std::array<double, 2> lift{0, 0};  // m each foot (left, right) is raised; only an unloaded one
  // m the left ankle is planned ahead of the right (a walk's feet, one put ahead of the other).
  // Each leg is tilted forward from the share's point between them (where the centre of mass is
  // planned) to its foot, so the weight carried from one foot to the other carries the body on.
  // Planned, not measured: tilts that followed the ankles as seen from the pelvis let the pelvis
  // turn freely on planted feet (steps in place fell 5-6 times in 2 x 2 x 30 s, none without).
  double left_ahead = 0;
  // The standing balance's load instead of the planned one (half the weight on each leg, in pitch
  // only), for comparison: with it the body is not carried over a foot (docs/basketball.md).
  bool half_and_half = false;
};

// Where a foot bears weight: its centre (the foot box's), heading frame.
Eigen::Vector3d foot_centre(const BodyModel& model, const BodyPose& pose, bool left);

// The centre of mass's velocity from an SMPL or SMPL-X self observation (heading frame): its
// bodies' velocities weighted by their masses. (The root's velocity rocks with the pelvis; fed
// back sideways it shook the body over at 1.5 rad per m/s where this one did not.)
Eigen::Vector3d centre_of_mass_velocity(const BodyModel& model, std::span<const float> observation);

// Overwrites the hip, knee and ankle targets of `action`. `com_velocity`: the centre of mass's,
// heading frame (centre_of_mass_velocity).
void hold_on_legs(const BodyModel& model, const BodyPose& pose, const Eigen::Vector3d& com_velocity,
                  const LegSupport& support, std::span<float> action,
                  const LegSupportGains& gains = {});

}  // namespace olympics::client::control
