// A planted boxer jolted: the scripted boxer stands alone in the sandbox (solo mode: one SMPL
// humanoid, the match's physics and fall rule), planted in its guard before a point it takes for
// its opponent (at its punching range, straight ahead; the point's chest out of reach, so it does
// not punch), and is given a velocity sideways, backward or between, as a push by the other does
// in a bout. Moving over 0.35 m/s it steps off the plant and must catch itself: in bouts 58 of 90
// step-offs from a plant came after such jolts, and the step after the jolt is what fell
// (docs/combat-sports.md, eleventh and twelfth rounds).
#include <gtest/gtest.h>
#include <ode/ode.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "framework/smpl_match.h"
#include "registry.h"
#include "scripted_boxing.h"
#include "solo_root.h"

namespace olympics::client {
namespace {

constexpr double kRange_m = 0.85;  // the boxer's punching range: it plants there

// How the jolt is given: every body the same velocity (the feet too, which the floor then stops),
// or a push high up (each body's velocity in proportion to its height, the feet's nearly none).
enum class Push { WholeBody, HighUp };

// Did the boxer fall within `seconds` of the jolt? It is jolted `settle_s` after it first plants;
// `velocity`: m/s at the root, its heading frame (x forward, y left).
bool falls_after_a_jolt(const StepGains& legs, Push push, const Eigen::Vector2d& velocity,
                        std::uint64_t seed, double settle_s, double seconds) {
  auto match = sports::sport_or_throw("sandbox").create({"solo", seed, 60.0, {}});
  std::vector<float> obs(match->obs_size()), act(match->action_size());
  ScriptedBoxingPolicy boxer(legs);
  boxer.start_alone(match->control_dt());
  const sports::SoloRoot spot = sports::solo_root(*match);
  const Eigen::Vector2d opponent =
      spot.position + Eigen::Rotation2Dd(spot.yaw) * Eigen::Vector2d(kRange_m, 0);
  auto tick = [&] {  // false once it has fallen
    match->observe(0, obs);
    const sports::SoloRoot now = sports::solo_root(*match);
    const Eigen::Vector2d line = Eigen::Rotation2Dd(-now.yaw) * (opponent - now.position);
    boxer.act_against(obs, {{line.x(), line.y(), 0}, {0, 0, 10}, false}, act);
    match->step({std::span<const float>(act)});
    return !match->outcome().done[0];
  };
  const double dt = match->control_dt();
  double planted_s = 0;
  for (int t = 0; planted_s < settle_s; ++t) {
    if (!tick()) return true;
    if (t * dt > 5) throw std::runtime_error("the boxer did not plant");
    planted_s = boxer.planted() ? planted_s + dt : 0;
  }
  const core::Humanoid& body = dynamic_cast<const sports::SmplMatch&>(*match).scene().humanoid(0);
  const Eigen::Vector2d v = Eigen::Rotation2Dd(sports::solo_root(*match).yaw) * velocity;
  const double root_z = dBodyGetPosition(body.ode_body(0))[2];
  for (int b = 0; b < body.body_count(); ++b) {
    const dReal* z = dBodyGetPosition(body.ode_body(b));
    const double share = push == Push::WholeBody ? 1 : std::max(0.0, z[2] / root_z);
    const dReal* was = dBodyGetLinearVel(body.ode_body(b));
    dBodySetLinearVel(body.ode_body(b), was[0] + share * v.x(), was[1] + share * v.y(), was[2]);
  }
  for (int t = 0; t < std::lround(seconds / dt); ++t)
    if (!tick()) return true;
  return false;
}

// Jolted at 0.4, 0.5 and 0.6 m/s, to the left, back-left, back, back-right and right, both ways
// of pushing, seeds 1-3 (90 runs): how many fell within 3 s.
int falls_over_jolts(const StepGains& legs, std::string& which) {
  int falls = 0;
  for (Push push : {Push::WholeBody, Push::HighUp})
    for (double speed : {0.4, 0.5, 0.6})
      for (int degrees = 90; degrees <= 270; degrees += 45)
        for (std::uint64_t seed : {1, 2, 3}) {
          const double a = degrees * M_PI / 180;
          if (falls_after_a_jolt(legs, push, speed * Eigen::Vector2d(std::cos(a), std::sin(a)),
                                 seed, 0.5 + 0.1 * seed, 3.0)) {
            ++falls;
            which += (push == Push::WholeBody ? " whole body " : " high up ") +
                     std::to_string(speed).substr(0, 3) + " m/s at " + std::to_string(degrees) +
                     " deg, seed " + std::to_string(seed) + ";";
          }
        }
  return falls;
}

// Measured (these 90 runs, the stance leg at 0.77 m): the boxer's plain first step (0.3 s, by the
// foot on the target's side, placed half a step of velocity ahead) fell in 17; a 0.2 s catch step
// at the capture point by the foot on the target's side in 14; by the foot on the falling side in
// 4 (back-right at 0.5-0.6 m/s). With the boxer's stance leg at 0.773 m (below): the plain step 14,
// the falling side's catch step 3.
TEST(CatchStep, AJoltedPlantedBoxerCatchesItselfOnItsFirstStep) {
  StepGains legs = boxing_step_gains();
  legs.catch_step_s = 0.2;
  legs.catch_on_the_falling_side = true;
  std::string which;
  EXPECT_LE(falls_over_jolts(legs, which), 5) << "fell:" << which;
}

// The boxer's own step off a plant (no catch step) on a stance leg held as straight as the leg
// solver allows, 0.773 m hip to ankle (the stepping controller's default: 0.77 m; the SMPL leg
// gives another 2 cm under the body's weight, docs/control.md). Measured (these 90 runs): 14
// fell; with the stance leg at 0.77 m (main's boxer) 17, at 0.76 m 21, at 0.74 m 28. In bouts
// (tuning seeds 1-60) falls went 0.298 -> 0.213 a minute (docs/combat-sports.md, fourteenth
// round).
TEST(CatchStep, TheBoxersPlainStepOffAPlantStandsOnAStraightStanceLeg) {
  std::string which;
  EXPECT_LE(falls_over_jolts(boxing_step_gains(), which), 15) << "fell:" << which;
}

}  // namespace
}  // namespace olympics::client
