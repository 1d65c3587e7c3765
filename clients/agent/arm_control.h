// Arm targets for the scripted baselines: a shoulder turned so the upper arm points along a
// direction (and rolled about it), an elbow bent.
//
// In the rest pose the right arm points along -y and the left along +y (a T-pose), every body's
// frame lined up with its parent's. A 3-hinge joint's target is the rotation
// R = Rx(a) Ry(b) Rz(c) from its parent's frame (MuJoCo's order), so any rotation can be asked
// for by its x-y-z Euler angles. The shoulder's parent is the thorax: directions given in the
// heading frame are turned into the thorax's frame as the observation shows it.
//
// The elbow folds the forearm towards the upper arm's x axis. Pointed ahead with no roll, that is
// towards the body's middle; a roll of +pi/2 (right arm) or -pi/2 (left arm) about the direction
// makes it fold upwards, as a boxer's guard does.
#pragma once

#include <Eigen/Geometry>
#include <span>

namespace olympics::client {

enum class Arm { Left, Right };

// Sets the three hinges of joint `body` to the rotation `q` (from its parent's frame).
void set_ball_joint(std::span<float> action, int body, const Eigen::Quaterniond& q);

// Points the upper arm along `direction` (heading frame), rolled by `roll` radians about it,
// from the self observation `o`.
void point_arm(std::span<const float> o, std::span<float> action, Arm arm,
               const Eigen::Vector3d& direction, double roll = 0);
// Bends the elbow by `radians` (0: straight).
void bend_elbow(std::span<float> action, Arm arm, double radians);

// An arm direction that follows a wanted one at a limited angular speed: a heavy arm (a sword, a
// glove) swung at once spins the whole body on its feet.
class ArmDirection {
 public:
  explicit ArmDirection(Arm arm) : direction_(0, arm == Arm::Right ? -1 : 1, 0) {}
  // Turns towards `wanted` by at most rate * dt radians; returns the new direction.
  const Eigen::Vector3d& follow(const Eigen::Vector3d& wanted, double rate, double dt);

 private:
  Eigen::Vector3d direction_;  // unit, heading frame; the rest pose to begin with
};

}  // namespace olympics::client
