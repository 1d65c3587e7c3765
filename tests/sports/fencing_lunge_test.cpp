// The scripted fencer's guard, footwork and lunge (clients/agent/control/guard_footwork.h).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/control_rate.h"
#include "registry.h"
#include "scripted_fencing.h"
#include "smpl_observation.h"

namespace olympics::client {
namespace {

TEST(FencingProbe, DISABLED_Trace) {
  const std::uint64_t seed = std::getenv("SEED") ? std::atoi(std::getenv("SEED")) : 1;
  const double seconds = std::getenv("SECS") ? std::atof(std::getenv("SECS")) : 10;
  auto match = sports::sport_or_throw("fencing").create({"1v1", seed, 0.0, {}});
  const auto layout = ObservationLayout::from_blocks(match->layout().observation);
  ScriptedFencingPolicy players[2];
  for (auto& p : players) p.start({"fencing", "1v1", core::kControlDt, layout, 69});
  std::vector<float> obs[2] = {std::vector<float>(match->obs_size()),
                               std::vector<float>(match->obs_size())};
  std::vector<float> act[2] = {std::vector<float>(69), std::vector<float>(69)};
  const int opp = layout.offset("opponent_root", "position");
  for (int tick = 0; tick < seconds * 30 && !match->outcome().match_over; ++tick) {
    for (int s = 0; s < 2; ++s) {
      match->observe(s, obs[s]);
      players[s].act(obs[s], act[s]);
    }
    const auto& o = obs[0];
    const auto fr = smpl::body_position(o, smpl::kRAnkle),
               bk = smpl::body_position(o, smpl::kLAnkle);
    const auto v = smpl::root_velocity(o);
    std::printf("%4d h%.2f D%.2f st%d v(%.2f %.2f) F(%.2f %.2f %.2f) B(%.2f %.2f %.2f)\n", tick,
                smpl::root_height(o), smpl::vec3(o, opp).head<2>().norm(),
                (int)players[0].debug_stage(), v.x(), v.y(), fr.x(), fr.y(), fr.z(), bk.x(), bk.y(),
                bk.z());
    match->step({std::span<const float>(act[0]), std::span<const float>(act[1])});
    for (const auto& ev : match->outcome().info.value("events", nlohmann::json::array()))
      std::printf("  EVENT %s\n", ev.dump().c_str());
  }
}

}  // namespace
}  // namespace olympics::client
