// How fast the stepping controller covers ground, in a real match (the sandbox's solo mode: one
// SMPL humanoid, the match's own physics and fall rule): distance covered in match time, never
// wall-clock time.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "registry.h"
#include "solo_root.h"
#include "step_controller.h"

namespace olympics::client {
namespace {

struct Walked {
  double at_1s = 0, at_2_5s = 0;  // m covered toward the target by then
  bool fell = false;
};

// One humanoid sent `metres` along `direction` (its own heading frame at the start) for
// `seconds`, keeping its starting heading.
Walked walk(const StepGains& gains, const Eigen::Vector2d& direction, double metres,
            double seconds) {
  auto match = sports::sport_or_throw("sandbox").create({"solo", 1, 60.0, {}});
  std::vector<float> obs(match->obs_size()), act(match->action_size());
  StepController legs(gains, match->control_dt());
  auto root = [&](double& yaw) {
    const sports::SoloRoot r = sports::solo_root(*match);
    yaw = r.yaw;
    return r.position;
  };
  double start_yaw = 0, yaw = 0;
  const Eigen::Vector2d start = root(start_yaw);
  const Eigen::Vector2d along = Eigen::Rotation2Dd(start_yaw) * direction.normalized();
  const Eigen::Vector2d target = start + metres * along;
  Walked w;
  const int ticks = static_cast<int>(std::lround(seconds / match->control_dt()));
  for (int tick = 1; tick <= ticks; ++tick) {
    match->observe(0, obs);
    const Eigen::Vector2d at = root(yaw);
    std::fill(act.begin(), act.end(), 0.0f);
    legs.act(obs, Eigen::Rotation2Dd(-yaw) * (target - at), start_yaw - yaw, act);
    match->step({std::span<const float>(act)});
    if (match->outcome().done[0]) return w.fell = true, w;
    const double covered = (root(yaw) - start).dot(along);
    if (std::abs(tick * match->control_dt() - 1.0) < 1e-6) w.at_1s = covered;
    if (std::abs(tick * match->control_dt() - 2.5) < 1e-6) w.at_2_5s = covered;
  }
  return w;
}

// The side-step shuffle covers ground sideways at 1 m/s once under way (measured 1.00-1.02 m/s
// between 1 and 2.5 s, 1.9 m in the first 2.5 s); the plain gait covers 0.5-0.6 m in 2.5 s.
TEST(StepControllerSpeed, SideSteppingCoversAMetreASecondSideways) {
  for (const Eigen::Vector2d& side : {Eigen::Vector2d(0, 1), Eigen::Vector2d(0, -1)}) {
    const Walked w = walk(side_stepping(), side, 3.0, 4.0);
    EXPECT_FALSE(w.fell) << "side-stepping toward " << side.transpose();
    EXPECT_GT((w.at_2_5s - w.at_1s) / 1.5, 0.95) << "m/s under way toward " << side.transpose();
    EXPECT_GT(w.at_2_5s, 1.7) << "m in 2.5 s toward " << side.transpose();
  }
}

TEST(StepControllerSpeed, ThePlainGaitIsSlowSideways) {
  // What side_stepping() is for, and that the defaults are as other sports measured them.
  const Walked w = walk({}, {0, 1}, 3.0, 2.5);
  EXPECT_FALSE(w.fell);
  EXPECT_LT(w.at_2_5s, 0.8);
  EXPECT_GT(w.at_2_5s, 0.3);
}

TEST(StepControllerSpeed, SideSteppingStillWalksForwardAndDiagonally) {
  for (const Eigen::Vector2d& way :
       {Eigen::Vector2d(1, 0), Eigen::Vector2d(1, 1), Eigen::Vector2d(1, -1)}) {
    const Walked w = walk(side_stepping(), way, 3.0, 6.0);
    EXPECT_FALSE(w.fell) << "toward " << way.transpose();
    EXPECT_GT(w.at_2_5s, 1.0) << "m in 2.5 s toward " << way.transpose();
  }
}

}  // namespace
}  // namespace olympics::client
