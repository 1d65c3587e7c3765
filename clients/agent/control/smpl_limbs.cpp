#include "control/smpl_limbs.h"

#include <cmath>

namespace olympics::client::control {

std::vector<LimbJoint> smpl_right_arm() {
  // Right arm at rest points along -y. Shoulder: x lowers the arm, z swings it forward, y rolls
  // it; the elbow folds forward about z (0..150 degrees), the wrist and hand turn the face
  // (wider than a human wrist: the server's joints have no limits, and a racket face held square
  // to the net in front of the body asks for it).
  return {
      {kSmplRShoulder, {-M_PI, -1.6, -1.2}, {M_PI, 1.6, 1.9}, {0.9, 0, 0.6}},
      {kSmplRElbow, {-0.1, -1.6, 0.0}, {0.1, 1.6, 2.6}, {0, 0, 0.6}},
      {kSmplRWrist, {-1.6, -1.6, -1.6}, {1.6, 1.6, 1.6}, {0, 0, 0}},
      {kSmplRHand, {-1.6, -1.6, -1.6}, {1.6, 1.6, 1.6}, {0, 0, 0}},
  };
}

std::vector<LimbJoint> smpl_right_arm_and_trunk() {
  // Spine and chest: roll (x), pitch (y) and turn (z) within a third of the original's +-60
  // degrees each, held toward upright; the thorax (shoulder girdle) nearly still.
  const Eigen::Vector3d trunk(0.35, 0.35, 0.45), girdle(0.1, 0.1, 0.1);
  std::vector<LimbJoint> chain = {
      {kSmplSpine, -trunk, trunk, Eigen::Vector3d::Zero(), 4},
      {kSmplChest, -trunk, trunk, Eigen::Vector3d::Zero(), 4},
      {kSmplRThorax, -girdle, girdle, Eigen::Vector3d::Zero(), 4},
  };
  for (const LimbJoint& j : smpl_right_arm()) chain.push_back(j);
  return chain;
}

}  // namespace olympics::client::control
