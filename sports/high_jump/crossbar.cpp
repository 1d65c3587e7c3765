#include "high_jump/crossbar.h"

#include <cmath>

namespace olympics::sports::high_jump {
namespace {

constexpr double kSupportThickness = 0.01;  // m
constexpr double kUprightSide = 0.04;       // m, square section
constexpr double kUprightAbove = 0.2;       // m the uprights reach above the bar (TR 27.5: 0.1)
constexpr double kDislodged = 0.02;         // m an end may drop before the bar counts as off

}  // namespace

Crossbar::Crossbar(core::PhysicsWorld& world, const HighJumpRules& rules, double x, double y,
                   double height)
    : rules_(rules), x_(x), y_(y), height_(height) {
  body_ = dBodyCreate(world.world());
  dMass m;
  // a solid round bar along its local z (ODE's capsule axis)
  dMassSetCylinderTotal(&m, rules_.bar_mass, 3, rules_.bar_radius, rules_.bar_length);
  dBodySetMass(body_, &m);
  geom_ =
      dCreateCapsule(world.space(), rules_.bar_radius, rules_.bar_length - 2 * rules_.bar_radius);
  dGeomSetBody(geom_, body_);
  tag_.entity = world.add_entity([](int, int) { return false; });
  tag_.body = 0, tag_.geom = 0;
  tag_.friction = 0.5;
  dGeomSetData(geom_, &tag_);
  for (int i = 0; i < 2; ++i) {
    supports_[i] = world.add_static_box(
        Eigen::Vector3d::Zero(),
        {0.5 * rules_.support_depth, 0.5 * rules_.support_length, 0.5 * kSupportThickness}, 0.5,
        0.0);
    uprights_[i] = world.add_static_box(Eigen::Vector3d::Zero(),
                                        {0.5 * kUprightSide, 0.5 * kUprightSide, 1.0}, 0.5, 0.0);
  }
  set(height);
}

Crossbar::~Crossbar() = default;  // the world destroys its bodies and geoms

void Crossbar::set(double height) {
  height_ = height;
  const double half_gap = 0.5 * rules_.upright_gap;
  for (int i = 0; i < 2; ++i) {
    const double side = i == 0 ? -1.0 : 1.0;
    dGeomSetPosition(supports_[i], x_, y_ + side * half_gap,
                     height_ - 2 * rules_.bar_radius - 0.5 * kSupportThickness);
    // The uprights stand just outside the supports and the bar's ends.
    const double upright_y =
        std::max(half_gap + 0.5 * rules_.support_length, 0.5 * rules_.bar_length) +
        0.5 * kUprightSide + 0.01;
    const double top = height_ + kUprightAbove;
    dGeomID u = uprights_[i];
    dGeomBoxSetLengths(u, kUprightSide, kUprightSide, top);
    dGeomSetPosition(u, x_, y_ + side * upright_y, 0.5 * top);
  }
  dBodySetPosition(body_, x_, y_, rest_centre_z());
  // local z (the bar's axis) along world y: a quarter turn about x
  const Eigen::Quaterniond q(Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()));
  const dQuaternion oq = {q.w(), q.x(), q.y(), q.z()};
  dBodySetQuaternion(body_, oq);
  dBodySetLinearVel(body_, 0, 0, 0);
  dBodySetAngularVel(body_, 0, 0, 0);
}

Eigen::Vector3d Crossbar::position() const {
  const dReal* p = dBodyGetPosition(body_);
  return {p[0], p[1], p[2]};
}

Eigen::Quaterniond Crossbar::orientation() const {
  const dReal* q = dBodyGetQuaternion(body_);
  return {q[0], q[1], q[2], q[3]};
}

Eigen::Vector3d Crossbar::end(int side) const {
  return position() + orientation() * Eigen::Vector3d(0, 0, side * 0.5 * rules_.bar_length);
}

bool Crossbar::in_place() const {
  // TR 27.2(a): the bar must remain on the supports. Each end no more than kDislodged below where
  // it rests, and its axis still over its support across the bar (within half the support's
  // depth of where it rests): a bar pushed along at its height, on a head or a chest, is off its
  // supports though its ends have not dropped.
  for (const int side : {-1, 1}) {
    const Eigen::Vector3d e = end(side);
    if (e.z() < rest_centre_z() - kDislodged || std::abs(e.x() - x_) > 0.5 * rules_.support_depth)
      return false;
  }
  return true;
}

}  // namespace olympics::sports::high_jump
