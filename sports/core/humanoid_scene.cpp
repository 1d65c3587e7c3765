#include "core/humanoid_scene.h"

namespace olympics::core {

HumanoidScene::HumanoidScene(const SceneSettings& settings)
    : settings_(settings), world_(std::make_unique<PhysicsWorld>(settings.world)) {}

int HumanoidScene::add_humanoid(const ModelSpec& spec, const RootPlacement& placement) {
  humanoids_.push_back(std::make_unique<Humanoid>(*world_, spec, placement));
  action_maps_.push_back(std::make_unique<ActionMap>(spec));
  return humanoid_count() - 1;
}

void HumanoidScene::set_action(int i, std::span<const float> action) {
  scratch_.resize(action_maps_[i]->size());
  action_maps_[i]->targets(action, scratch_);
  humanoids_[i]->set_joint_targets(scratch_);
}

void HumanoidScene::physics_step() {
  const double h = settings_.physics_dt();
  for (auto& h_ptr : humanoids_) h_ptr->prepare_step(h);
  world_->step(h);
  ++physics_steps_;
}

void HumanoidScene::tick() {
  for (int s = 0; s < settings_.substeps; ++s) physics_step();
}

}  // namespace olympics::core
