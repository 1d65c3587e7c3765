// The control toolkit's standing balance (clients/agent/control/standing_balance.h): SMPL-X
// players, whose leg drives are softer than gravity's toppling stiffness, stand in a basketball
// 1v1 at the control rate from the observation alone; the free-throw shooter's ankle-and-hip
// strategy, the same way, falls.
#include <gtest/gtest.h>

#include <functional>

#include "control/body_model.h"
#include "control/standing_balance.h"
#include "registry.h"
#include "scripted_basketball.h"
#include "smplx_observation.h"

namespace olympics::sports::basketball {
namespace {

using Stand = std::function<void(std::span<const float>, std::span<float>)>;

// Falls in `seconds` of a 1v1 of `seed` in which both players only stand, by `stand`.
int falls_standing(std::uint64_t seed, double seconds, const Stand& stand) {
  auto m = sport_or_throw("basketball").create({"1v1", seed, seconds, {}});
  std::vector<float> obs[2], act[2];
  int falls = 0;
  while (!m->outcome().match_over) {
    for (int s = 0; s < 2; ++s) {
      obs[s].assign(m->obs_size(), 0), act[s].assign(m->action_size(), 0);
      m->observe(s, obs[s]);
      stand(obs[s], act[s]);
    }
    m->step({std::span<const float>(act[0]), std::span<const float>(act[1])});
    for (const auto& e : m->outcome().info.value("events", nlohmann::json::array()))
      falls += e.value("call", "") == "fall";
  }
  return falls;
}

TEST(ControlStandingBalance, SmplxPlayersStandThroughA1v1WhereTheAnkleAndHipStrategyFalls) {
  // Seeds 1 and 2, 20 s each (the check ball, the ball dropped, the shot clock's restart at 12 s).
  // Measured: no fall with the balance (none in 2 x 60 s either); the shooter's ankle and hip
  // strategy: both players fall within 7 s, again after each stand-up.
  const auto model = client::control::BodyModel::humanoid(core::HumanoidKind::SmplX);
  const Stand balanced = [&](std::span<const float> o, std::span<float> a) {
    client::control::hold_standing_balance(model, model.pose_from_observation(o),
                                           client::smplx::vec3(o, client::smplx::kLinVel), a);
  };
  const Stand ankles_and_hips = [](std::span<const float> o, std::span<float> a) {
    client::stand_on_ankles_and_hips(o, a, client::FreeThrowShot{});
  };
  int with_balance = 0, with_ankles_and_hips = 0;
  for (std::uint64_t seed : {1, 2}) {
    with_balance += falls_standing(seed, 20, balanced);
    with_ankles_and_hips += falls_standing(seed, 20, ankles_and_hips);
  }
  EXPECT_EQ(with_balance, 0);
  EXPECT_GE(with_ankles_and_hips, 4);
}

}  // namespace
}  // namespace olympics::sports::basketball
