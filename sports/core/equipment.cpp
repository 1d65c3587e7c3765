#include "core/equipment.h"

#include <stdexcept>

namespace olympics::core {
namespace {

// A cylinder lies along its local z; this turns local z onto the hand's -y axis.
const Eigen::Quaterniond kAlongMinusY(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));

// The striking disc at y = `centre_y` in the hand frame (axis: the hand's z): a mass-only geom (the
// ball meets it through BallFlight, not ODE), and the face the ball is swept against.
void add_face(EquipmentSpec& e, const char* name, double radius, double half_thickness,
              double centre_y, double density) {
  GeomSpec g;
  g.name = name;
  g.shape = GeomShape::Cylinder;
  g.pos = {0, centre_y, 0};
  g.radius = radius;
  g.half_length = half_thickness;
  g.density = density;
  g.collides = false;
  e.geoms.push_back(g);
  e.face = {radius, half_thickness};
  e.face_centre = g.pos;
}

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
  e.geoms = {handle};
  add_face(e, "racket_head", 0.15, 0.02, -0.35, 150);
  e.restitution = 0.8;
  e.friction = 0.8;
  return e;
}

EquipmentSpec table_tennis_paddle() {
  EquipmentSpec e;
  e.name = "paddle";
  e.replaces_hand_geoms = true;
  add_face(e, "paddle", 0.08, 0.01, -0.12, 200);
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
