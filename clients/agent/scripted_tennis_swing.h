// The tennis stroke's swing in joint space: the racket arm held in the one posture that meets
// the ball (the face at the contact point, its normal the planned one), turned as one about the
// vertical through the shoulder. Only the shoulder's rotation changes during the swing, so the
// face runs along a known arc and comes to the contact point with the planned normal when the
// turn comes back to zero. The swing before it solved inverse kinematics every tick along that
// arc: the elbow and wrist wandered from tick to tick and the arm, asked for the contact rate
// from a standstill, lagged (docs/racket-sports.md, issue 29 fourth round).
#pragma once

#include <Eigen/Geometry>
#include <span>
#include <vector>

#include "control/body_model.h"
#include "control/limb_ik.h"

namespace olympics::client {

// The turn of the arm `tau` seconds from contact (negative before it) and how fast it turns:
// held `back` radians back, then from rest at a constant acceleration to `rate` rad/s at
// contact (the turn back at zero), then on at that rate to `follow` radians and held there.
struct SwingTurn {
  double angle = 0, rate = 0;
  double acceleration = 0;  // rad/s², while it speeds up to `rate`
};
SwingTurn swing_turn(double tau, double rate, double back, double follow);

// Writes the arm's joints of `action`: `contact` (per joint of `ik`, relative to its parent, e.g.
// a LimbIk solution for the contact pose in `pose`) with its first joint (the shoulder) turned
// by `turn.angle` radians about the vertical (left positive), turning at `turn.rate`; gravity
// compensation for `gravity_scale` times the weight of the pose wanted and velocity feed-forward
// as target offsets (control/drive_target.h); with `hold_turning`, also the turn's centripetal and
// tangential load on each joint (BodyModel::turning_torque; a fast swing flings the racket out and
// drags it back otherwise: the serve's face, turned at some 15 rad/s, met the ball 15 cm low).
void drive_turned_arm(const control::BodyModel& model, const control::LimbIk& ik,
                      const control::BodyPose& pose, const std::vector<Eigen::Matrix3d>& contact,
                      const SwingTurn& turn, double gravity_scale, std::span<float> action,
                      bool hold_turning = false);

// Writes the free (left) arm's shoulder: held out straight to the side and turned about the
// vertical the other way from the racket arm's `turn`, so that its reaction cancels part of the
// racket arm's. Swung alone, a 10 m/s serve spun the body 0.5-0.75 rad on its feet before contact;
// with it, about 0.2 rad (docs/racket-sports.md, the tennis serve).
void drive_counter_arm(const control::BodyModel& model, const control::BodyPose& pose,
                       const SwingTurn& turn, double gravity_scale, std::span<float> action);

}  // namespace olympics::client
