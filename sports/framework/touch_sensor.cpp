#include "framework/touch_sensor.h"

namespace olympics::sports {

TouchSensor::TouchSensor(std::vector<int> slot_entities, std::vector<int> slot_teams,
                         TargetTest is_target, double min_force_n, double refractory_s)
    : slot_entities_(std::move(slot_entities)),
      slot_teams_(std::move(slot_teams)),
      is_target_(std::move(is_target)),
      min_force_n_(min_force_n),
      refractory_s_(refractory_s) {}

int TouchSensor::slot_of(int entity) const {
  for (size_t s = 0; s < slot_entities_.size(); ++s)
    if (slot_entities_[s] == entity) return static_cast<int>(s);
  return -1;
}

std::vector<Touch> TouchSensor::collect(const core::PhysicsWorld& world, double time) {
  std::map<std::tuple<int, int, int>, Touch> strongest;
  for (const auto& c : world.sensed_contacts()) {
    if (!c.other || c.normal_force < min_force_n_) continue;  // the floor, or too light
    const int attacker = slot_of(c.sensor->entity), defender = slot_of(c.other->entity);
    if (attacker < 0 || defender < 0 || slot_teams_[attacker] == slot_teams_[defender]) continue;
    const int body = c.other->body;
    if (!is_target_(body, c.other->geom)) continue;
    const auto key = std::make_tuple(attacker, c.sensor->body, c.sensor->geom);
    auto& best = strongest[key];
    if (best.attacker >= 0 && best.force >= c.normal_force) continue;
    best = {attacker,       defender, c.sensor->body, c.sensor->geom, body,
            c.normal_force, time,     c.position,     c.normal};
  }
  std::vector<Touch> touches;
  for (auto& [key, touch] : strongest) {
    auto last = last_touch_.find(key);
    const bool refractory = last != last_touch_.end() && time - last->second < refractory_s_;
    last_touch_[key] = time;
    if (!refractory) touches.push_back(touch);
  }
  return touches;
}

}  // namespace olympics::sports
