#include "standing_balance.h"

#include <algorithm>

namespace olympics::sports {
namespace {

using Eigen::Vector3d;

// The SMPL and SMPL-X legs (HUMANOID.md, HUMANOID-SMPLX.md): joint j moves body j.
constexpr int kHip[2] = {1, 5}, kToe[2] = {4, 8};
constexpr double kGravity = 9.81;

double& target(std::vector<double>& targets, int body, int axis) {
  return targets[3 * (body - 1) + axis];
}

}  // namespace

StandingBalance::StandingBalance(core::Humanoid& humanoid, std::vector<dBodyID> carried)
    : humanoid_(humanoid), carried_(std::move(carried)) {}

StandingBalance::Mass StandingBalance::mass_of(const std::vector<int>& without) const {
  Mass m;
  const auto add = [&](dBodyID body) {
    dMass mass;
    dBodyGetMass(body, &mass);
    const dReal* x = dBodyGetPosition(body);  // ODE bodies sit at their centres of mass
    const dReal* v = dBodyGetLinearVel(body);
    m.kg += mass.mass;
    m.centre += mass.mass * Vector3d(x[0], x[1], x[2]);
    m.velocity += mass.mass * Vector3d(v[0], v[1], v[2]);
  };
  for (int b = 0; b < humanoid_.body_count(); ++b)
    if (std::find(without.begin(), without.end(), b) == without.end()) add(humanoid_.ode_body(b));
  for (dBodyID body : carried_) add(body);
  m.centre /= m.kg;
  m.velocity /= m.kg;
  return m;
}

void StandingBalance::write_leg_targets(std::vector<double>& targets) const {
  const core::Humanoid& h = humanoid_;
  const Mass whole = mass_of({});
  // What each joint holds up: above the hips the trunk, above the knees also the thighs, above
  // the ankles also the shanks.
  const Mass held[3] = {mass_of({1, 2, 3, 4, 5, 6, 7, 8}), mass_of({2, 3, 4, 6, 7, 8}),
                        mass_of({3, 4, 7, 8})};
  const Vector3d feet =
      0.5 * (h.body_state(kHip[0] + 2).position + h.body_state(kHip[1] + 2).position);
  const Vector3d off = whole.centre - (feet + Vector3d(ahead, 0, 0));
  const Vector3d up = h.body_state(0).orientation * Vector3d::UnitZ();
  const double roll = side_p * off.y() + side_d * whole.velocity.y();
  for (int leg = 0; leg < 2; ++leg) {
    for (int k = 0; k < 3; ++k) {  // hip, knee, ankle
      const int joint = kHip[leg] + k;
      const double kp = h.spec().bodies[joint].hinges[1].kp;
      // The parent side's weight acts about the joint; the drive pushes its child (the leg
      // below) the other way: a torque kp (target - angle) on it. Half the weight per leg.
      double pitch_torque =
          0.5 * held[k].kg * kGravity * (held[k].centre.x() - h.body_state(joint).position.x());
      double roll_target = 0;
      if (k == 0) {
        pitch_torque -= 0.5 * upright * up.x();
        roll_target = roll + 0.5 * upright * up.y() / kp;
      } else if (k == 2) {
        pitch_torque += 0.5 * (forward_p * off.x() + forward_d * whole.velocity.x());
        roll_target = -roll;
      }
      target(targets, joint, 0) = roll_target;
      target(targets, joint, 1) = pitch_torque / kp;
      target(targets, joint, 2) = 0;
    }
    for (int axis = 0; axis < 3; ++axis) target(targets, kToe[leg], axis) = 0;
  }
}

}  // namespace olympics::sports
