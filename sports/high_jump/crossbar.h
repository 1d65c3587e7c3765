// One high-jump installation: two uprights, two supports and the crossbar, a free rigid body
// that rests on the supports and falls when knocked (TR 27.6-27.8). The bar lies along world y.
#pragma once

#include <ode/ode.h>

#include <Eigen/Geometry>

#include "core/physics_world.h"
#include "high_jump/high_jump_rules.h"

namespace olympics::sports::high_jump {

class Crossbar {
 public:
  // The installation with its bar centred at (x, y), resting at `height` (the bar's top).
  Crossbar(core::PhysicsWorld& world, const HighJumpRules& rules, double x, double y,
           double height);
  Crossbar(const Crossbar&) = delete;
  Crossbar& operator=(const Crossbar&) = delete;
  ~Crossbar();

  // Supports at `height` and the bar back on them at rest.
  void set(double height);
  double height() const { return height_; }
  // Both ends of the bar no more than 2 cm below where they rest and still over their supports
  // across the bar: not dislodged.
  bool in_place() const;
  Eigen::Vector3d position() const;
  Eigen::Quaterniond orientation() const;
  Eigen::Vector3d end(int side) const;  // side -1 or +1 along the bar
  dBodyID body() const { return body_; }
  const core::GeomTag& tag() const { return tag_; }

 private:
  double rest_centre_z() const { return height_ - rules_.bar_radius; }

  HighJumpRules rules_;
  double x_, y_, height_;
  dBodyID body_ = nullptr;
  dGeomID geom_ = nullptr;
  core::GeomTag tag_;
  dGeomID supports_[2] = {nullptr, nullptr};
  dGeomID uprights_[2] = {nullptr, nullptr};
};

}  // namespace olympics::sports::high_jump
