#include "boxing/gloves.h"

namespace olympics::sports::boxing {

equipment::EquipmentSpec glove(const std::string& hand, const Eigen::Vector3d& hand_box_centre) {
  equipment::EquipmentSpec e;
  e.name = "glove";
  e.hand = hand;
  e.replaces_hand_geoms = true;
  core::GeomSpec g;
  g.name = hand + "_glove";
  g.shape = core::GeomShape::Sphere;
  g.pos = hand_box_centre;
  g.radius = 0.08;
  g.density = 400;  // 0.858 kg
  g.friction = 0.5;
  g.sensor = true;
  e.geoms = {g};
  return e;
}

Eigen::Vector3d glove_centre(const core::ModelSpec& spec, int hand_body) {
  const auto& geoms = spec.bodies[hand_body].geoms;
  return geoms.empty() ? Eigen::Vector3d::Zero() : geoms.front().pos;
}

}  // namespace olympics::sports::boxing
