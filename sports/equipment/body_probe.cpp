#include "equipment/body_probe.h"

#include <algorithm>
#include <cmath>

namespace olympics::sports::equipment {

BodyProbe::BodyProbe(double ball_radius) : radius_(ball_radius) {
  sphere_ = dCreateSphere(nullptr, ball_radius);
}

BodyProbe::~BodyProbe() { dGeomDestroy(sphere_); }

std::optional<BodyTouch> BodyProbe::first_touch(
    core::PhysicsWorld& world, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
    const std::function<bool(int entity, int body)>& ignore) {
  const Eigen::Vector3d lo = p0.cwiseMin(p1).array() - radius_;
  const Eigen::Vector3d hi = p0.cwiseMax(p1).array() + radius_;
  const int samples = 1 + static_cast<int>(std::ceil((p1 - p0).norm() / radius_));
  std::optional<BodyTouch> first;
  int first_sample = samples + 1;
  const int n = dSpaceGetNumGeoms(world.space());
  for (int g = 0; g < n; ++g) {
    dGeomID geom = dSpaceGetGeom(world.space(), g);
    auto* tag = static_cast<core::GeomTag*>(dGeomGetData(geom));
    if (!tag || tag->entity < 0 || ignore(tag->entity, tag->body)) continue;
    dReal box[6];
    dGeomGetAABB(geom, box);
    if (box[1] < lo.x() || box[0] > hi.x() || box[3] < lo.y() || box[2] > hi.y() ||
        box[5] < lo.z() || box[4] > hi.z())
      continue;
    for (int s = 0; s < std::min(samples, first_sample); ++s) {
      const Eigen::Vector3d c = p0 + (p1 - p0) * (samples == 1 ? 1.0 : double(s) / (samples - 1));
      dGeomSetPosition(sphere_, c.x(), c.y(), c.z());
      dContactGeom contact;
      if (dCollide(sphere_, geom, 1, &contact, sizeof contact) == 0) continue;
      Eigen::Vector3d normal(contact.normal[0], contact.normal[1], contact.normal[2]);
      const Eigen::Vector3d to_ball =
          c - Eigen::Vector3d(contact.pos[0], contact.pos[1], contact.pos[2]);
      if (normal.dot(to_ball) < 0) normal = -normal;
      first = BodyTouch{tag->entity, tag->body, c, normal};
      first_sample = s;
      break;
    }
  }
  return first;
}

}  // namespace olympics::sports::equipment
