// A world with humanoids in it, stepped at the control rate: the physics every sport builds on.
//
// One control tick (kControlHz) = `substeps` physics steps of control_dt / substeps each; PD drives
// are refreshed before every physics step. A scene is stepped by one thread at a time; several
// scenes may be stepped in parallel threads and each stays bit-for-bit reproducible.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "core/action_map.h"
#include "core/control_rate.h"
#include "core/humanoid.h"
#include "core/physics_world.h"

namespace olympics::core {

struct SceneSettings {
  double control_dt = kControlDt;
  int substeps = 4;  // physics at 120 Hz: chosen by measurement, see docs/physics.md
  WorldSettings world;
  double physics_dt() const { return control_dt / substeps; }
};

class HumanoidScene {
 public:
  explicit HumanoidScene(const SceneSettings& settings = {});

  int add_humanoid(const ModelSpec& spec, const RootPlacement& placement = {});
  int humanoid_count() const { return static_cast<int>(humanoids_.size()); }
  // Swaps which index names humanoids a and b, not their place in the physics world: the one
  // created first stays first in ODE's solver order (a sport that draws that order per match).
  void swap_humanoids(int a, int b) {
    std::swap(humanoids_[a], humanoids_[b]);
    std::swap(action_maps_[a], action_maps_[b]);
  }
  Humanoid& humanoid(int i) { return *humanoids_[i]; }
  const Humanoid& humanoid(int i) const { return *humanoids_[i]; }
  const ActionMap& action_map(int i) const { return *action_maps_[i]; }

  // Sets PD targets from a policy action; throws std::invalid_argument on bad size or NaN/Inf.
  void set_action(int humanoid, std::span<const float> action);
  void tick();          // one control tick
  void physics_step();  // one physics step (a tick is `substeps` of these)

  PhysicsWorld& world() { return *world_; }
  const PhysicsWorld& world() const { return *world_; }
  const SceneSettings& settings() const { return settings_; }
  long physics_steps() const { return physics_steps_; }

 private:
  SceneSettings settings_;
  std::unique_ptr<PhysicsWorld> world_;
  std::vector<std::unique_ptr<Humanoid>> humanoids_;
  std::vector<std::unique_ptr<ActionMap>> action_maps_;
  std::vector<double> scratch_;
  long physics_steps_ = 0;
};

}  // namespace olympics::core
