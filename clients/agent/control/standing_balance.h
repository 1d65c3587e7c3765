// Standing on both feet at the control rate, from the observation: PD with gravity compensation
// and a centre-of-mass balance, for humanoids whose leg drives are softer than gravity's toppling
// stiffness (SMPL-X: hips and knees 250 N·m/rad, ankles 150, against m g h of about 600). It is
// the test fixture tests/sports/standing_balance.h (which reads the simulator at 120 Hz) brought
// to what a client sees at 30 Hz: each hip, knee and ankle targets the torque that holds up the
// weight above it, half per leg, over its kp; the centre of mass is held `ahead` of the ankles by
// the ankles' pitch and sideways by the hips and ankles rolling together (the legs and pelvis are
// a parallelogram); the hips right the pelvis.
//
// Measured (docs/control.md, "Measured facts"): two SMPL-X players standing in a 1v1 (seeds 1-2,
// tuning), no fall in 2 x 60 s with the gains below; the free-throw shooter's ankle-and-hip
// strategy falls 4-7 s after each stand-up, the fixture's own 120 Hz gains sooner.
#pragma once

#include <limits>
#include <span>

#include "control/body_model.h"

namespace olympics::client::control {

struct StandingGains {
  double forward_p = 600;  // N·m per m of the centre of mass off its place, ankles' pitch
  double forward_d = 120;  // N·m per m/s
  double side_p = 2;       // rad of roll per m sideways
  double side_d = 0.5;     // rad per m/s
  double upright = 100;    // N·m per unit of the pelvis's tilt, hips
  double ahead = 0.03;     // m: the centre of mass held this far ahead of the ankles
  // rad: the ankles' pitch target capped at this much toes-down (none by default). A player whose
  // reach carries its centre of mass to the front of its feet may cap the push that would lift
  // its heels (the standing dribble, docs/basketball.md).
  double max_toes_down = std::numeric_limits<double>::infinity();
};

// Overwrites the hip, knee and ankle targets of `action` (SMPL or SMPL-X: their legs are bodies
// 1-3 and 5-7 in both). `root_velocity`: the observed root velocity, heading frame.
void hold_standing_balance(const BodyModel& model, const BodyPose& pose,
                           const Eigen::Vector3d& root_velocity, std::span<float> action,
                           const StandingGains& gains = {});

}  // namespace olympics::client::control
