#include "athletics/athlete_probe.h"

#include <algorithm>
#include <string>

namespace olympics::sports::athletics {

AthleteContacts athlete_contacts(const core::PhysicsWorld& world, int entity,
                                 const core::GeomTag* surface, const Footprint& surface_area) {
  AthleteContacts c;
  auto on_surface_at = [&c](double x) {
    c.on_surface = true;
    c.surface_near_x = std::min(c.surface_near_x, x);
    c.surface_far_x = std::max(c.surface_far_x, x);
  };
  for (const auto& g : world.ground_contacts()) {
    if (g.geom->entity != entity) continue;
    if (surface && surface_area.contains(g.position)) {
      on_surface_at(g.position.x());
    } else {
      c.on_ground = true;
      c.ground_front_x = std::max(c.ground_front_x, g.position.x());
    }
  }
  if (surface)
    for (const auto& s : world.sensed_contacts())
      if (s.sensor == surface && s.other && s.other->entity == entity)
        on_surface_at(s.position.x());
  return c;
}

double foremost_x(const core::Humanoid& humanoid) {
  double front = -1e9;
  for (int b = 0; b < humanoid.body_count(); ++b)
    for (dGeomID g = dBodyGetFirstGeom(humanoid.ode_body(b)); g; g = dBodyGetNextGeom(g)) {
      dReal aabb[6];
      dGeomGetAABB(g, aabb);
      front = std::max(front, static_cast<double>(aabb[1]));
    }
  return front;
}

std::vector<int> foot_bodies(const core::Humanoid& humanoid) {
  std::vector<int> feet;
  for (int b = 0; b < humanoid.body_count(); ++b) {
    const std::string& name = humanoid.spec().bodies[b].name;
    if (name.find("Ankle") != std::string::npos || name.find("Toe") != std::string::npos)
      feet.push_back(b);
  }
  return feet;
}

double feet_front_x(const core::Humanoid& humanoid, const std::vector<int>& feet) {
  double front = -1e9;
  for (int b : feet) front = std::max(front, humanoid.body_state(b).position.x());
  return front;
}

Eigen::Vector3d mean_body_position(const core::Humanoid& humanoid) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int b = 0; b < humanoid.body_count(); ++b) sum += humanoid.body_state(b).position;
  return sum / humanoid.body_count();
}

}  // namespace olympics::sports::athletics
