// Does a ball moving along a segment touch a body of a humanoid? Balls flown by BallFlight are
// not ODE bodies, so the referee asks here: a sphere geom outside any space is placed along the
// segment (at most a radius apart, so it cannot skip a limb) and collided with each geom whose
// bounding box the segment comes near.
#pragma once

#include <ode/ode.h>

#include <Eigen/Core>
#include <functional>
#include <optional>

#include "core/physics_world.h"

namespace olympics::sports::equipment {

struct BodyTouch {
  int entity = -1, body = -1;  // from the touched geom's GeomTag
  Eigen::Vector3d centre;      // ball centre at the touch
  Eigen::Vector3d normal;      // unit, from the body towards the ball
};

class BodyProbe {
 public:
  explicit BodyProbe(double ball_radius);
  ~BodyProbe();
  BodyProbe(const BodyProbe&) = delete;
  BodyProbe& operator=(const BodyProbe&) = delete;

  struct Options {
    bool arena = false;   // also the static arena's geoms (entity -1), not the ground plane
    bool refine = false;  // bisect to the first overlapping centre within a millimetre
  };
  // The first touch along p0 -> p1 with a geom of an entity (>= 0) that `ignore` does not
  // exclude.
  std::optional<BodyTouch> first_touch(core::PhysicsWorld& world, const Eigen::Vector3d& p0,
                                       const Eigen::Vector3d& p1,
                                       const std::function<bool(int entity, int body)>& ignore,
                                       const Options& options);
  std::optional<BodyTouch> first_touch(core::PhysicsWorld& world, const Eigen::Vector3d& p0,
                                       const Eigen::Vector3d& p1,
                                       const std::function<bool(int entity, int body)>& ignore) {
    return first_touch(world, p0, p1, ignore, Options{});
  }

 private:
  // The contact of the probe sphere centred at `c` with `geom`, if they overlap.
  std::optional<BodyTouch> touch_at(dGeomID geom, const core::GeomTag& tag,
                                    const Eigen::Vector3d& c);

  double radius_;
  dGeomID sphere_;
};

}  // namespace olympics::sports::equipment
