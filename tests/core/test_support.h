// Helpers shared by the physics core tests.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "core/humanoid_assets.h"
#include "core/humanoid_scene.h"

namespace olympics::core::testing {

// ../shared/fixtures holds public MJCF files; tests that need them skip loudly where it is absent.
inline std::string fixture(const std::string& name) {
  return std::string(OLYMPICS_FIXTURE_DIR) + "/" + name;
}
inline bool have_fixtures() { return std::filesystem::exists(OLYMPICS_FIXTURE_DIR); }

inline const ModelSpec& smpl() {
  static const ModelSpec spec = load_humanoid(HumanoidKind::Smpl);
  return spec;
}
inline const ModelSpec& smplx() {
  static const ModelSpec spec = load_humanoid(HumanoidKind::SmplX);
  return spec;
}

inline std::vector<float> random_action(std::mt19937& rng, int size, float amplitude = 1.0f) {
  std::uniform_real_distribution<float> u(-amplitude, amplitude);
  std::vector<float> a(size);
  for (auto& x : a) x = u(rng);
  return a;
}

}  // namespace olympics::core::testing
