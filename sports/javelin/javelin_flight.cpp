#include "javelin/javelin_flight.h"

#include <Eigen/Geometry>
#include <cmath>

#include "core/humanoid_scene.h"
#include "core/physics_world.h"
#include "javelin/javelin_implement.h"

namespace olympics::sports::javelin {

JavelinLanding fly(const JavelinSpec& spec, bool aerodynamics, const JavelinRelease& r,
                   double max_s) {
  const core::SceneSettings scene;
  core::PhysicsWorld world(scene.world);
  Javelin j(world, spec);
  const double deg = M_PI / 180.0;
  j.place(r.grip,
          Eigen::Quaterniond(Eigen::AngleAxisd(-r.attitude_deg * deg, Eigen::Vector3d::UnitY())));
  const Eigen::Vector3d v(r.speed * std::cos(r.angle_deg * deg), 0,
                          r.speed * std::sin(r.angle_deg * deg));
  j.set_motion(v, Eigen::Vector3d(0, -r.pitch_rate, 0));  // tip up = about -y
  const double h = scene.physics_dt();
  JavelinLanding out;
  for (double t = 0; t < max_s; t += h) {
    if (aerodynamics) j.add_aerodynamic_load();
    world.step(h);
    bool any = false, head_only = true;
    for (const auto& g : world.ground_contacts()) {
      if (g.geom->entity != j.entity()) continue;
      if (!any || g.geom->geom == Javelin::kHeadGeom) out.first_touch = g.position;
      any = true;
      head_only = head_only && g.geom->geom == Javelin::kHeadGeom;
    }
    if (any) {
      out.landed = true;
      out.tip_first = head_only;
      out.t = t + h;
      return out;
    }
  }
  return out;
}

}  // namespace olympics::sports::javelin
