// The SMPL-X humanoid's arms as the control toolkit drives them (HUMANOID-SMPLX.md): shoulder,
// elbow and wrist, whose box is the palm (SMPL-X has no hand body; the fingers hang off the
// wrist). The right arm has the SMPL arm's limits and preferred posture (smpl_limbs.h); the left
// is its mirror image.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "control/limb_ik.h"

namespace olympics::client::control {

// SMPL-X body indices the toolkit names.
inline constexpr int kSmplxLShoulder = 15, kSmplxLElbow = 16, kSmplxLWrist = 17,
                     kSmplxRShoulder = 34, kSmplxRElbow = 35, kSmplxRWrist = 36;

// Shoulder, elbow and wrist of one arm; its base is the thorax.
std::vector<LimbJoint> smplx_arm(bool right);
// The palm's centre (the wrist box's centre) and the palm's outward normal, wrist frame: the
// palm faces -z (down in the T-pose, the side the fingers close to).
Eigen::Vector3d smplx_palm_centre(bool right);
inline Eigen::Vector3d smplx_palm_normal() { return -Eigen::Vector3d::UnitZ(); }
// Half the palm box's thickness: from its centre to the skin of the palm.
inline constexpr double kSmplxPalmHalfThickness = 0.0122;

}  // namespace olympics::client::control
