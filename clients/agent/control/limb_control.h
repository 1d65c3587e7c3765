// Driving a limb to a pose: inverse kinematics for where it should be now and a tick later, then
// PD targets with gravity compensation and velocity feed-forward (drive_target.h), written into
// the action. Also the trunk held straight against gravity while a limb swings.
#pragma once

#include <span>
#include <vector>

#include "control/drive_target.h"
#include "control/limb_ik.h"

namespace olympics::client::control {

class LimbControl {
 public:
  // `gravity_scale`: the weight compensated, in multiples of the true one (drive_target.h).
  LimbControl(const BodyModel& model, LimbIk ik, double gravity_scale = kLoadedDriveSoftness)
      : model_(model), ik_(std::move(ik)), gravity_scale_(gravity_scale) {}

  // Writes the limb's joints so that it is at `now` one tick from now and heading for `next` a
  // tick after; `compensate` false leaves gravity out (to measure what it is worth).
  const LimbSolution& drive(const BodyPose& pose, const LimbGoal& now, const LimbGoal& next,
                            double tick_s, std::span<float> action, bool compensate = true);
  // Forgets the last solution (the next solve starts from the observed pose).
  void reset() { last_.relative.clear(); }

  const LimbIk& ik() const { return ik_; }

 private:
  const BodyModel& model_;
  LimbIk ik_;
  double gravity_scale_;
  LimbSolution last_;
};

// Holds `bodies` (e.g. the torso, spine and chest) at `rest` relative to their parents against the
// weight they carry in `pose`.
void hold_against_gravity(const BodyModel& model, const BodyPose& pose, std::span<const int> bodies,
                          std::span<float> action, double gravity_scale = kLoadedDriveSoftness);

// Adds to the leg targets already in `action` (hips, knees, ankles) what each joint needs to hold
// up the body above it, half each, as when standing on both feet: the legs' drives otherwise
// sag under the body's weight, the more so as the arms carry weight out in front.
void hold_standing_legs(const BodyModel& model, const BodyPose& pose, std::span<float> action,
                        double gravity_scale = kLoadedDriveSoftness);

}  // namespace olympics::client::control
