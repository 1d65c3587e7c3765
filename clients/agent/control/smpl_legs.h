// The SMPL humanoid's legs as the control toolkit drives them (a foot is another LimbIk end
// point): hip, knee and ankle with Euler x-y-z limits from the original's XML (hips +-90
// degrees, the knee folding backward only, ankles +-45 sideways) and a slightly bent knee as the
// preferred posture.
#pragma once

#include <vector>

#include "control/limb_ik.h"

namespace olympics::client::control {

// SMPL leg body indices (HUMANOID.md section 1.1).
inline constexpr int kSmplLHip = 1, kSmplLKnee = 2, kSmplLAnkle = 3, kSmplRHip = 5, kSmplRKnee = 6,
                     kSmplRAnkle = 7;

// Hip, knee and ankle of one leg; its base is the pelvis. Hip y < 0 swings the thigh forward,
// knee y > 0 folds the shank back.
std::vector<LimbJoint> smpl_leg(bool left);

// Points of the foot, in the ankle body's frame: the middle of the toe's front face (what a
// toe-poke or a push meets the ball with) and the ankle joint itself (a planted foot).
Eigen::Vector3d smpl_toe_front(bool left);

}  // namespace olympics::client::control
