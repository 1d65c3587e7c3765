#include "fencing/epee.h"

namespace olympics::sports::fencing {
namespace {

// Capsules and cylinders lie along their local z; this turns it onto the hand's -y axis.
const Eigen::Quaterniond kAlongMinusY(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));

core::GeomSpec part(const char* name, core::GeomShape shape, double centre_y, double radius,
                    double half_length, double mass) {
  core::GeomSpec g;
  g.name = name;
  g.shape = shape;
  g.pos = {0, centre_y, 0};
  g.quat = kAlongMinusY;
  g.radius = radius;
  g.half_length = half_length;
  g.mass = mass;
  g.friction = 0.3;  // steel on steel, steel on a jacket
  return g;
}

}  // namespace

equipment::EquipmentSpec epee() {
  equipment::EquipmentSpec e;
  e.name = "epee";
  core::GeomSpec grip = part("epee_grip", core::GeomShape::Sphere, -0.04, 0.015, 0, 0.20);
  grip.collides = false;  // inside the hand
  core::GeomSpec guard = part("epee_guard", core::GeomShape::Cylinder, -0.11, 0.05, 0.005, 0.25);
  // The blade's capsule ends 3 cm short of the tip, so only the tip's sphere touches there.
  core::GeomSpec blade = part("epee_blade", core::GeomShape::Capsule, -0.535, 0.007, 0.415, 0.30);
  core::GeomSpec tip = part("epee_tip", core::GeomShape::Sphere, -0.968, 0.012, 0, 0.02);
  tip.sensor = true;
  e.geoms = {grip, guard, blade, tip};
  return e;
}

int epee_geom_count() { return static_cast<int>(epee().geoms.size()); }

}  // namespace olympics::sports::fencing
