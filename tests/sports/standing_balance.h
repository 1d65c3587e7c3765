// A standing balance for tests in which a humanoid must stand on its own while something else is
// measured (the SMPL-X player holding the ball by friction). It reads the simulator's state and
// runs at the physics rate, so it is a test fixture, not a policy: policies see observations at
// the control rate.
//
// Why PD targets alone cannot stand a body: SMPL-X's drives (HUMANOID-SMPLX.md: hips and knees
// 250 N·m/rad, ankles 150) are softer than gravity's toppling stiffness of a standing body
// (m g h, about 600 N·m/rad), so with fixed targets it sags and falls within 1.5 s. Each leg joint
// here targets its rest angle offset by the torque it must hold (the weight above it times the
// lever, halved between the legs, over its kp): PD plus gravity compensation. On top of that the
// centre of mass is held over the feet: forward-back by the ankles' pitch, sideways by the ankles
// and hips rolling together (the two legs and the pelvis are a parallelogram; one joint alone
// only fights the other) and the pelvis kept upright by the hips.
#pragma once

#include <ode/ode.h>

#include <vector>

#include "core/humanoid.h"

namespace olympics::sports {

class StandingBalance {
 public:
  // `carried`: bodies the humanoid holds (a ball), whose weight it bears.
  explicit StandingBalance(core::Humanoid& humanoid, std::vector<dBodyID> carried = {});
  void carry(dBodyID body) { carried_.push_back(body); }

  // Overwrites the hip, knee and ankle targets in `targets` (radians, action order); call before
  // every physics step.
  void write_leg_targets(std::vector<double>& targets) const;

  // Forward-back: ankle torque per m of the centre of mass off its place over the feet and per m/s
  // of its velocity; sideways: parallelogram roll, rad per m and per m/s; the pelvis righted by
  // the hips, N·m per unit of tilt; where the centre of mass is held, ahead of the ankles (m).
  double forward_p = 1000, forward_d = 150, side_p = 4, side_d = 1, upright = 200, ahead = 0.03;

 private:
  struct Mass {
    double kg = 0;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero(), velocity = Eigen::Vector3d::Zero();
  };
  // The humanoid's bodies but `without`, and what it carries.
  Mass mass_of(const std::vector<int>& without) const;

  core::Humanoid& humanoid_;
  std::vector<dBodyID> carried_;
};

}  // namespace olympics::sports
