// Stepping in place with a boxer's guard up, in a real match (the sandbox's solo mode: one SMPL
// humanoid, the match's own physics and fall rule). The guard holds the arms out in front, which
// puts the centre of mass 4 cm ahead of the root; feet placed about the root then leave the body
// falling forward onto every step, and the scripted boxers drifted into each other and circled
// (docs/combat-sports.md). Placed about the centre of mass, the feet hold the spot.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "control/body_model.h"
#include "registry.h"
#include "scripted_boxing.h"
#include "solo_root.h"
#include "step_controller.h"

namespace olympics::client {
namespace {

struct Drift {
  Eigen::Vector2d per_s{0, 0};  // m/s of the root after the first second, starting heading frame
  bool fell = false;
};

// One humanoid keeps stepping (it never settles to stand) on the spot where it started, its
// starting heading held, its guard up, for `seconds`.
Drift step_in_place(StepGains gains, std::uint64_t seed, double seconds) {
  auto match = sports::sport_or_throw("sandbox").create({"solo", seed, 60.0, {}});
  std::vector<float> obs(match->obs_size()), act(match->action_size());
  gains.start_m = 0;   // it steps from the first tick...
  gains.arrive_m = 0;  // ...and never stops
  StepController legs(gains, match->control_dt());
  const control::BodyModel model = control::BodyModel::humanoid(core::HumanoidKind::Smpl);
  const sports::SoloRoot spot = sports::solo_root(*match);
  sports::SoloRoot after_1s = spot;
  Drift d;
  const int ticks = static_cast<int>(std::lround(seconds / match->control_dt()));
  for (int tick = 1; tick <= ticks; ++tick) {
    match->observe(0, obs);
    const sports::SoloRoot now = sports::solo_root(*match);
    std::fill(act.begin(), act.end(), 0.0f);
    hold_guard(obs, act);
    legs.set_centre_of_mass(model.centre_of_mass(model.pose_from_observation(obs)));
    legs.act(obs, Eigen::Rotation2Dd(-now.yaw) * (spot.position - now.position), spot.yaw - now.yaw,
             act);
    match->step({std::span<const float>(act)});
    if (match->outcome().done[0]) return d.fell = true, d;
    if (std::abs(tick * match->control_dt() - 1.0) < 1e-6) after_1s = sports::solo_root(*match);
  }
  const Eigen::Vector2d moved = sports::solo_root(*match).position - after_1s.position;
  d.per_s = Eigen::Rotation2Dd(-spot.yaw) * moved / (seconds - 1.0);
  return d;
}

// Measured (seeds 1-3, 5 s after the first): placed about the root, 0.144-0.147 m/s forward;
// about the centre of mass, at most 0.004 m/s forward or back and 0.012 sideways.
TEST(StepInPlace, WithTheGuardUpTheFeetPlacedAboutTheCentreOfMassHoldTheSpot) {
  StepGains gains = boxing_step_gains();
  gains.centre_of_mass_placement = 1;
  for (std::uint64_t seed : {1, 2, 3}) {
    const Drift d = step_in_place(gains, seed, 6.0);
    EXPECT_FALSE(d.fell) << "seed " << seed;
    EXPECT_LT(d.per_s.norm(), 0.04) << "seed " << seed << ": m/s " << d.per_s.transpose();
  }
}

}  // namespace
}  // namespace olympics::client
