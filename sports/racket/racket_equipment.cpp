#include "racket/racket_equipment.h"

namespace olympics::sports::racket {
namespace {

// A cylinder lies along its local z; this turns local z onto the hand's -y axis.
const Eigen::Quaterniond kAlongMinusY(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));

}  // namespace

equipment::EquipmentSpec tennis_racket() {
  equipment::EquipmentSpec e;
  e.name = "racket";
  core::GeomSpec handle;
  handle.name = "racket_handle";
  handle.shape = core::GeomShape::Capsule;
  handle.pos = {0, -0.175, 0};
  handle.quat = kAlongMinusY;
  handle.radius = 0.016;
  handle.half_length = 0.175;
  handle.mass = M_PI * 0.016 * 0.016 * 0.35 * 500;  // the cylinder's, 0.14 kg
  e.geoms = {handle};
  equipment::add_striking_face(e, "racket_head", 0.15, 0.02, -0.35, 150);
  e.restitution = 0.8;
  e.friction = 0.8;
  return e;
}

equipment::EquipmentSpec table_tennis_paddle() {
  equipment::EquipmentSpec e;
  e.name = "paddle";
  e.replaces_hand_geoms = true;
  equipment::add_striking_face(e, "paddle", 0.08, 0.01, -0.12, 200);
  e.restitution = 0.85;
  e.friction = 0.8;
  return e;
}

}  // namespace olympics::sports::racket
