#include "control/smplx_limbs.h"

#include "control/smpl_limbs.h"

namespace olympics::client::control {

std::vector<LimbJoint> smplx_arm(bool right) {
  // The SMPL right arm's shoulder, elbow and wrist (its hand body has no SMPL-X counterpart).
  std::vector<LimbJoint> arm = smpl_right_arm();
  arm.pop_back();
  const int bodies[] = {right ? kSmplxRShoulder : kSmplxLShoulder,
                        right ? kSmplxRElbow : kSmplxLElbow, right ? kSmplxRWrist : kSmplxLWrist};
  for (size_t k = 0; k < arm.size(); ++k) {
    LimbJoint& j = arm[k];
    j.body = bodies[k];
    if (right) continue;
    // Mirrored in the sagittal plane (y -> -y): turns about x and z change sign, about y not.
    const Eigen::Vector3d lo = j.lo, hi = j.hi;
    j.lo = {-hi.x(), lo.y(), -hi.z()};
    j.hi = {-lo.x(), hi.y(), -lo.z()};
    j.preferred = {-j.preferred.x(), j.preferred.y(), -j.preferred.z()};
  }
  return arm;
}

Eigen::Vector3d smplx_palm_centre(bool right) {
  // The wrist box's centre (HUMANOID-SMPLX.md): R (-.0029, -.0537, -.0044), L (-.0031, .0523,
  // -.0013).
  return right ? Eigen::Vector3d(-0.0029, -0.0537, -0.0044)
               : Eigen::Vector3d(-0.0031, 0.0523, -0.0013);
}

}  // namespace olympics::client::control
