#include "core/equipment.h"

#include <stdexcept>

namespace olympics::core {
namespace {

// A cylinder lies along its local z; these turn local z onto the hand's -y axis.
const Eigen::Quaterniond kAlongMinusY(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));

}  // namespace

EquipmentSpec tennis_racket() {
  EquipmentSpec e;
  e.name = "racket";
  GeomSpec handle;
  handle.name = "racket_handle";
  handle.shape = GeomShape::Capsule;
  handle.pos = {0, -0.175, 0};
  handle.quat = kAlongMinusY;
  handle.radius = 0.016;
  handle.half_length = 0.175;
  handle.mass = M_PI * 0.016 * 0.016 * 0.35 * 500;  // the cylinder's, 0.14 kg
  GeomSpec head;
  head.name = "racket_head";
  head.shape = GeomShape::Cylinder;
  head.pos = {0, -0.35, 0};
  head.radius = 0.15;
  head.half_length = 0.02;
  head.density = 150;
  head.collides = false;
  e.geoms = {handle, head};
  e.face = {0.15, 0.02};
  e.face_centre = head.pos;
  e.restitution = 0.8;
  e.friction = 0.8;
  return e;
}

EquipmentSpec table_tennis_paddle() {
  EquipmentSpec e;
  e.name = "paddle";
  e.replaces_hand_geoms = true;
  GeomSpec blade;
  blade.name = "paddle";
  blade.shape = GeomShape::Cylinder;
  blade.pos = {0, -0.12, 0};
  blade.radius = 0.08;
  blade.half_length = 0.01;
  blade.density = 200;
  blade.collides = false;
  e.geoms = {blade};
  e.face = {0.08, 0.01};
  e.face_centre = blade.pos;
  e.restitution = 0.85;
  e.friction = 0.8;
  return e;
}

void attach_equipment(ModelSpec& spec, const EquipmentSpec& equipment) {
  const int hand = spec.body_index(equipment.hand);
  if (hand < 0)
    throw std::invalid_argument(spec.source + ": no body \"" + equipment.hand + "\" to hold the " +
                                equipment.name);
  auto& geoms = spec.bodies[hand].geoms;
  if (equipment.replaces_hand_geoms) geoms.clear();
  geoms.insert(geoms.end(), equipment.geoms.begin(), equipment.geoms.end());
}

Pose equipment_face_pose(const Humanoid& humanoid, int hand_body, const EquipmentSpec& equipment) {
  const BodyState hand = humanoid.body_state(hand_body);
  return {hand.position + hand.orientation * equipment.face_centre, hand.orientation};
}

}  // namespace olympics::core
