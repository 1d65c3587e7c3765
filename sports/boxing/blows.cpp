#include "boxing/blows.h"

#include <Eigen/Geometry>

#include "combat/combat_observation.h"

namespace olympics::sports::boxing {

BlowSensor::BlowSensor(std::array<int, 2> slot_entities, std::array<int, 2> hands,
                       std::array<Eigen::Vector3d, 2> glove_centres, std::vector<bool> is_target)
    : slot_entities_(slot_entities),
      hands_(hands),
      glove_centres_(glove_centres),
      is_target_(std::move(is_target)) {}

int BlowSensor::slot_of(int entity) const {
  for (int s = 0; s < 2; ++s)
    if (slot_entities_[s] == entity) return s;
  return -1;
}

int BlowSensor::hand_of(int body) const {
  for (int h = 0; h < 2; ++h)
    if (hands_[h] == body) return h;
  return -1;
}

std::vector<GloveArrival> BlowSensor::collect(const core::PhysicsWorld& world, double time) {
  // Per glove, its strongest contact with the other boxer's target in this step.
  std::array<std::array<const core::SensedContact*, 2>, 2> strongest{};
  for (const auto& c : world.sensed_contacts()) {
    if (!c.other) continue;  // the floor
    const int attacker = slot_of(c.sensor->entity), hand = hand_of(c.sensor->body);
    if (attacker < 0 || hand < 0 || slot_of(c.other->entity) != 1 - attacker) continue;
    if (!is_target_[c.other->body]) continue;
    const core::SensedContact*& best = strongest[attacker][hand];
    if (!best || c.normal_force > best->normal_force) best = &c;
  }
  std::vector<GloveArrival> arrivals;
  for (int s = 0; s < 2; ++s)
    for (int h = 0; h < 2; ++h) {
      const bool touching = strongest[s][h] != nullptr;
      if (touching && !touching_[s][h]) arrivals.push_back(arrival(*strongest[s][h], s, h, time));
      touching_[s][h] = touching;
    }
  return arrivals;
}

GloveArrival BlowSensor::arrival(const core::SensedContact& c, int attacker, int hand,
                                 double time) const {
  GloveArrival a;
  a.attacker = attacker, a.hand = hand;
  a.target_body = c.other->body;
  a.time = time;
  a.force = c.normal_force;
  a.normal = c.normal;
  if (before_[0].empty()) return a;  // no state before the step: neither closing nor a blow
  const core::BodyState& glove_body = before_[attacker][hands_[hand]];
  const core::BodyState& target = before_[1 - attacker][c.other->body];
  // Both bodies' velocities at the contact point, before the step's contact impulse.
  const Eigen::Vector3d on_glove =
      glove_body.orientation.inverse() * (c.position - glove_body.position);
  const Eigen::Vector3d on_target = target.orientation.inverse() * (c.position - target.position);
  const Eigen::Vector3d relative = combat::point_on_body(glove_body, on_glove).velocity -
                                   combat::point_on_body(target, on_target).velocity;
  a.closing_speed = -relative.dot(c.normal);
  // The knuckle face: the glove's side away from the wrist; the contact lies towards -normal.
  const Eigen::Vector3d knuckles = glove_body.orientation * glove_centres_[hand];
  if (knuckles.norm() > 1e-9) a.knuckle_cos = knuckles.normalized().dot(-c.normal);
  return a;
}

bool is_blow(const GloveArrival& a, const BlowRules& rules) {
  return a.closing_speed >= rules.min_closing_speed && a.knuckle_cos >= rules.knuckle_cone_cos;
}

}  // namespace olympics::sports::boxing
