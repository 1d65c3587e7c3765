// What the base of every SMPL match owns for its sport: the random generator, seeded from the
// match seed, and the control rate it announces, which is the scene's own.
#include <gtest/gtest.h>

#include <random>

#include "core/humanoid_assets.h"
#include "framework/smpl_match.h"
#include "registry.h"

namespace olympics::sports {
namespace {

// A bare SMPL match: one player, nothing to referee, stepped at `control_hz`.
class BareMatch : public SmplMatch {
 public:
  BareMatch(const ModeSpec& mode, const MatchSettings& settings, int control_hz)
      : SmplMatch(mode, smpl_layout({}, {{"alive", 1.0, "+1 a tick"}}, {}), settings,
                  scene_at(control_hz)) {
    add_player(core::load_humanoid(core::HumanoidKind::Smpl), {});
  }
  std::uint64_t draw() { return rng()(); }

 private:
  static core::SceneSettings scene_at(int control_hz) {
    core::SceneSettings scene;
    scene.control_dt = 1.0 / control_hz;
    return scene;
  }
  void write_task_observation(int, const HeadingFrame&, ObservationWriter&) const override {}
  void settle_tick() override {}
};

const ModeSpec kSolo{"solo", {0}, "one player"};

TEST(MatchBase, TheRandomGeneratorIsSeededFromTheMatchSeed) {
  MatchSettings settings;
  settings.seed = 1234, settings.time_limit_s = 1;
  BareMatch match(kSolo, settings, 30);
  std::mt19937_64 expected(1234);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(match.draw(), expected());
}

TEST(MatchBase, TheControlRateIsTheScenes) {
  MatchSettings settings;
  settings.time_limit_s = 2;
  BareMatch at_60(kSolo, settings, 60);
  EXPECT_EQ(at_60.control_hz(), 60);
  EXPECT_DOUBLE_EQ(at_60.control_dt(), 1.0 / 60);
  EXPECT_DOUBLE_EQ(at_60.time_limit_s(), 2.0);
}

TEST(MatchBase, EverySportAnnouncesThirtyHertz) {
  for (const auto& name : sport_names()) {
    const Sport& sport = sport_or_throw(name);
    MatchSettings settings;
    settings.mode = sport.modes().names().front();
    EXPECT_EQ(sport.create(settings)->control_hz(), 30) << name;
  }
}

}  // namespace
}  // namespace olympics::sports
