// The SMPL humanoid's limbs as the control toolkit drives them: joints in order from the trunk,
// with Euler x-y-z limits (anatomical, from the original's XML where it had them, HUMANOID.md)
// and a preferred posture that picks one arm pose among the many that reach a point.
#pragma once

#include <vector>

#include "control/limb_ik.h"

namespace olympics::client::control {

// SMPL body indices the toolkit names (HUMANOID.md section 1.1).
inline constexpr int kSmplTorso = 9, kSmplSpine = 10, kSmplChest = 11, kSmplRThorax = 19,
                     kSmplRShoulder = 20, kSmplRElbow = 21, kSmplRWrist = 22, kSmplRHand = 23;

// Shoulder, elbow, wrist and hand of the right arm (the racket arm); its base is the thorax.
std::vector<LimbJoint> smpl_right_arm();
// The same arm from the spine up: the spine and chest lean and turn the shoulder toward a ball
// the arm alone does not reach (whole upper body); its base is the torso.
std::vector<LimbJoint> smpl_right_arm_and_trunk();

}  // namespace olympics::client::control
