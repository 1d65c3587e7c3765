#include "equipment/body_probe.h"

#include <algorithm>
#include <cmath>

namespace olympics::sports::equipment {

BodyProbe::BodyProbe(double ball_radius) : radius_(ball_radius) {
  sphere_ = dCreateSphere(nullptr, ball_radius);
}

BodyProbe::~BodyProbe() { dGeomDestroy(sphere_); }

std::optional<BodyTouch> BodyProbe::touch_at(dGeomID geom, const core::GeomTag& tag,
                                             const Eigen::Vector3d& c) {
  dGeomSetPosition(sphere_, c.x(), c.y(), c.z());
  dContactGeom contact;
  if (dCollide(sphere_, geom, 1, &contact, sizeof contact) == 0) return std::nullopt;
  Eigen::Vector3d normal(contact.normal[0], contact.normal[1], contact.normal[2]);
  const Eigen::Vector3d to_ball =
      c - Eigen::Vector3d(contact.pos[0], contact.pos[1], contact.pos[2]);
  if (normal.dot(to_ball) < 0) normal = -normal;
  return BodyTouch{tag.entity, tag.body, c, normal};
}

std::optional<BodyTouch> BodyProbe::first_touch(
    core::PhysicsWorld& world, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
    const std::function<bool(int entity, int body)>& ignore, const Options& options) {
  const Eigen::Vector3d lo = p0.cwiseMin(p1).array() - radius_;
  const Eigen::Vector3d hi = p0.cwiseMax(p1).array() + radius_;
  const int samples = 1 + static_cast<int>(std::ceil((p1 - p0).norm() / radius_));
  const auto sample = [&](double s) {
    return Eigen::Vector3d(p0 + (p1 - p0) * (samples == 1 ? 1.0 : s / (samples - 1)));
  };
  std::optional<BodyTouch> first;
  int first_sample = samples + 1;
  dGeomID first_geom = nullptr;
  const int n = dSpaceGetNumGeoms(world.space());
  for (int g = 0; g < n; ++g) {
    dGeomID geom = dSpaceGetGeom(world.space(), g);
    auto* tag = static_cast<core::GeomTag*>(dGeomGetData(geom));
    if (!tag || (tag->entity < 0 && !options.arena) || ignore(tag->entity, tag->body)) continue;
    dReal box[6];
    dGeomGetAABB(geom, box);
    if (box[1] < lo.x() || box[0] > hi.x() || box[3] < lo.y() || box[2] > hi.y() ||
        box[5] < lo.z() || box[4] > hi.z())
      continue;
    for (int s = 0; s < std::min(samples, first_sample); ++s) {
      auto touch = touch_at(geom, *tag, sample(s));
      if (!touch) continue;
      first = touch, first_sample = s, first_geom = geom;
      break;
    }
  }
  if (!first || !options.refine || first_sample == 0) return first;
  // Between the last clear sample and the first overlapping one.
  double clear = first_sample - 1, hit = first_sample;
  const auto* tag = static_cast<core::GeomTag*>(dGeomGetData(first_geom));
  while ((sample(hit) - sample(clear)).norm() > 1e-3) {
    const double mid = 0.5 * (clear + hit);
    if (auto touch = touch_at(first_geom, *tag, sample(mid))) {
      first = touch, hit = mid;
    } else {
      clear = mid;
    }
  }
  return first;
}

}  // namespace olympics::sports::equipment
