// A standing two-footed jump for the SMPL humanoid, as whole-body joint targets against time:
// a crouch (minimum-jerk into the crouch pose), a push (the targets step to the push pose: the
// drives extend hips, knees and ankles and swing the arms as fast as they can) and a flight pose
// held from then on (legs brought forward for a landing, or tucked over a bar). Open loop: the
// jumper starts it standing still; the poses and times are found by a search per event (the
// scripted long and high jumpers, docs/athletics.md).
#pragma once

#include <span>

namespace olympics::client::control {

// One pose of the jump, both sides alike (rad): hip pitch (< 0 the thigh forward), knee flexion
// (> 0 folded), ankle pitch, trunk pitch per trunk joint (torso, spine, chest; > 0 forward),
// and the arms: shoulder roll and twist, mirrored left to right.
struct JumpPose {
  double hip = 0, knee = 0, ankle = 0, trunk = 0, arm_x = 0, arm_z = 0;
};

struct StandingJump {
  JumpPose crouch, push, flight;
  double crouch_s = 0.5;  // s into the crouch
  double push_s = 0.2;    // s of the push, then the flight pose
  // The parameters as one vector, for a search over them (poses in the order above, then the
  // two times).
  static constexpr int kParameters = 20;
  static StandingJump from(std::span<const double> x);
  void to(std::span<double> x) const;
};

// Writes the legs', trunk's and arms' targets `t` seconds into the jump; other joints are left
// as they are.
void write_standing_jump(const StandingJump& jump, double t, std::span<float> action);

}  // namespace olympics::client::control
