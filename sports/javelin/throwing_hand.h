// The SMPL-X throwing hand (the right): its palm (the R_Wrist body: SMPL-X has no hand body, the
// wrist's box is the palm), its geoms, where the cord sits in it, and how far its fingers are
// closed, measured from the bodies' rotations (not the targets the athlete sends).
#pragma once

#include <ode/ode.h>

#include <Eigen/Core>
#include <vector>

#include "core/humanoid.h"

namespace olympics::sports::javelin {

class ThrowingHand {
 public:
  explicit ThrowingHand(const core::Humanoid& humanoid);
  int palm() const { return palm_; }
  // The cord's middle in the palm's frame: under the palm (its -z side, towards which the
  // fingers close), across it.
  static Eigen::Vector3d cord_in_palm() { return {0.0, -0.075, -0.035}; }
  Eigen::Vector3d cord_point(const core::Humanoid& h) const;
  // The palm's and the fingers' geoms (the grip's hand).
  std::vector<dGeomID> geoms(const core::Humanoid& h) const;
  // The mean flexion (rad) of the four fingers' twelve links about their x hinges, towards the
  // palm (the thumb left out): 0 straight, ~0.3 closed round a cord.
  double finger_flexion(const core::Humanoid& h) const;

 private:
  int palm_ = -1;
  std::vector<int> hand_bodies_;  // the palm and every finger link
  std::vector<int> fingers_;      // index, middle, ring, pinky links
};

}  // namespace olympics::sports::javelin
