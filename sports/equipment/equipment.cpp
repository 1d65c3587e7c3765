#include "equipment/equipment.h"

#include <stdexcept>

namespace olympics::sports::equipment {
void add_striking_face(EquipmentSpec& e, const char* name, double radius, double half_thickness,
                       double centre_y, double density) {
  core::GeomSpec g;
  g.name = name;
  g.shape = core::GeomShape::Cylinder;
  g.pos = {0, centre_y, 0};
  g.radius = radius;
  g.half_length = half_thickness;
  g.density = density;
  g.collides = false;
  e.geoms.push_back(g);
  e.face = {radius, half_thickness};
  e.face_centre = g.pos;
}

void attach_equipment(core::ModelSpec& spec, const EquipmentSpec& equipment) {
  const int hand = spec.body_index(equipment.hand);
  if (hand < 0)
    throw std::invalid_argument(spec.source + ": no body \"" + equipment.hand + "\" to hold the " +
                                equipment.name);
  auto& geoms = spec.bodies[hand].geoms;
  if (equipment.replaces_hand_geoms) geoms.clear();
  for (core::GeomSpec g : equipment.geoms) {
    g.held = true;
    geoms.push_back(std::move(g));
  }
}

Pose equipment_face_pose(const core::Humanoid& humanoid, int hand_body,
                         const EquipmentSpec& equipment) {
  const core::BodyState hand = humanoid.body_state(hand_body);
  return {hand.position + hand.orientation * equipment.face_centre, hand.orientation};
}

}  // namespace olympics::sports::equipment
