#include "golf/golf_club.h"

#include <cmath>

namespace olympics::sports::golf {
namespace {

constexpr double kShaftRadius = 0.008;

}  // namespace

ClubSpec putter() { return {"putter", 0.75, 3.0, {0.015, 0.0125, 0.05}, 0.33, 0.12, 0.8, 0.8}; }

ClubSpec driver() { return {"driver", 1.14, 10.5, {0.025, 0.025, 0.055}, 0.20, 0.10, 0.83, 0.8}; }

ClubSpec seed_club() {
  return {"seed_club", 1.14, 0.0, {0.0125, 0.01, 0.025}, 0.20, 0.10, 0.8, 0.8};
}

equipment::EquipmentSpec club_equipment(const ClubSpec& club) {
  equipment::EquipmentSpec e;
  e.name = club.name;
  // The shaft, from the grip to the head's top, along -y (a capsule lies along its local z).
  const double shaft = club.length - club.head_half.y();
  core::GeomSpec s;
  s.name = "club_shaft";
  s.shape = core::GeomShape::Capsule;
  s.pos = {0, -0.5 * shaft, 0};
  s.quat = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
  s.radius = kShaftRadius;
  s.half_length = 0.5 * shaft;
  s.mass = club.shaft_mass;
  s.friction = 0.8;
  core::GeomSpec h;
  h.name = kClubHeadGeom;
  h.shape = core::GeomShape::Box;
  h.pos = club_head_offset(club);
  h.quat = club_head_orientation(club);
  h.half_extents = club.head_half;
  h.mass = club.head_mass;
  h.friction = club.friction;
  e.geoms = {s, h};
  e.restitution = club.restitution;
  e.friction = 0.8;
  return e;
}

}  // namespace olympics::sports::golf
