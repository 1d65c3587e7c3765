#include "hurdles/hurdle.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace olympics::sports::hurdles {
namespace {

constexpr double kBarDepth = 0.02, kBarHeight = 0.07;  // TR 22.3: 10-25 mm by 70 mm
constexpr double kUprightSide = 0.03;
constexpr double kBaseLength = 0.70, kBaseSide = 0.04, kBaseHeight = 0.03;  // TR 22.3: <= 0.70 m
constexpr double kBaseFront = 0.02;  // m the bases reach past the top bar's plane: the pivot
constexpr double kBarMass = 1.0, kUprightMass = 0.5, kBaseMass = 0.75;  // kg; the rest: weights
constexpr double kWeightLength = 0.12;

}  // namespace

std::vector<HurdlePart> hurdle_parts(const HurdlesRules& r) {
  const double h = r.hurdle_height, half_w = 0.5 * r.hurdle_width;
  const double side = half_w - 0.5 * kUprightSide;  // the uprights' and bases' y
  const double upright_low = kBaseHeight, upright_high = h - kBarHeight;
  std::vector<HurdlePart> parts = {
      {{0, 0, h - 0.5 * kBarHeight}, {0.5 * kBarDepth, half_w, 0.5 * kBarHeight}, kBarMass, true}};
  for (double s : {-1.0, 1.0}) {
    parts.push_back({{0, s * side, 0.5 * (upright_low + upright_high)},
                     {0.5 * kUprightSide, 0.5 * kUprightSide, 0.5 * (upright_high - upright_low)},
                     kUprightMass,
                     true});
    parts.push_back({{kBaseFront - 0.5 * kBaseLength, s * side, 0.5 * kBaseHeight},
                     {0.5 * kBaseLength, 0.5 * kBaseSide, 0.5 * kBaseHeight},
                     kBaseMass,
                     true});
  }
  // The counterweights: the rest of the mass, placed so that the centre of mass lies
  // d = F H / (M g) behind the pivot (the bases' front edge).
  double frame_mass = 0, frame_moment = 0;
  for (const auto& p : parts) frame_mass += p.mass, frame_moment += p.mass * p.centre.x();
  const double weights = r.hurdle_mass - frame_mass;
  const double com_x = kBaseFront - r.tip_force_kgf * h / r.hurdle_mass;
  const double weight_x = (r.hurdle_mass * com_x - frame_moment) / weights;
  const double back = kBaseFront - kBaseLength + 0.5 * kWeightLength;
  if (weights <= 0 || weight_x < back || weight_x > -0.5 * kWeightLength)
    throw std::invalid_argument(
        "hurdle: no counterweight on 0.70 m bases gives a tipping force of " +
        std::to_string(r.tip_force_kgf) + " kgf at " + std::to_string(h) +
        " m; give a tipping force within 3.6-4.0 kgf");
  for (double s : {-1.0, 1.0})
    parts.push_back({{weight_x, s * side, 0.5 * kBaseHeight},
                     {0.5 * kWeightLength, 0.5 * kBaseSide, 0.5 * kBaseHeight},
                     0.5 * weights,
                     false});
  return parts;
}

double tipping_force_kgf(const std::vector<HurdlePart>& parts, double height) {
  double mass = 0, moment = 0;
  for (const auto& p : parts) mass += p.mass, moment += p.mass * p.centre.x();
  return mass * (kBaseFront - moment / mass) / height;
}

Hurdle::Hurdle(core::PhysicsWorld& world, const HurdlesRules& rules, double x, double y,
               dSpaceID parent)
    : parts_(hurdle_parts(rules)), height_(rules.hurdle_height) {
  dMass total;
  dMassSetZero(&total);
  double mass = 0;
  for (const auto& p : parts_) {
    com_ += p.mass * p.centre;
    mass += p.mass;
  }
  com_ /= mass;
  for (const auto& p : parts_) {
    dMass m;
    dMassSetBoxTotal(&m, p.mass, 2 * p.half.x(), 2 * p.half.y(), 2 * p.half.z());
    const Eigen::Vector3d at = p.centre - com_;  // ODE wants the centre of mass at the origin
    dMassTranslate(&m, at.x(), at.y(), at.z());
    dMassAdd(&total, &m);
  }
  body_ = dBodyCreate(world.world());
  total.c[0] = total.c[1] = total.c[2] = 0;  // the sum of the parts about their common centre
  dBodySetMass(body_, &total);
  dBodySetPosition(body_, x + com_.x(), y + com_.y(), com_.z());
  tag_.entity = world.add_entity([](int, int) { return false; });
  tag_.body = 0, tag_.geom = 0;
  tag_.friction = 0.8;
  // Its geoms in a space of their own inside the world's: the world's broad phase (a simple
  // space, every pair) then meets one entry per hurdle, not five, and leaves a sleeping hurdle
  // out with one flag.
  space_ = dSimpleSpaceCreate(parent ? parent : world.space());
  for (const auto& p : parts_) {
    if (!p.collides) continue;
    dGeomID g = dCreateBox(space_, 2 * p.half.x(), 2 * p.half.y(), 2 * p.half.z());
    dGeomSetBody(g, body_);
    const Eigen::Vector3d at = p.centre - com_;
    dGeomSetOffsetPosition(g, at.x(), at.y(), at.z());
    dGeomSetData(g, &tag_);
  }
}

void Hurdle::set_awake(bool awake) {
  if (awake == awake_) return;
  awake_ = awake;
  if (awake) {
    dBodyEnable(body_);
    dGeomEnable(reinterpret_cast<dGeomID>(space_));
  } else {
    dBodySetLinearVel(body_, 0, 0, 0);
    dBodySetAngularVel(body_, 0, 0, 0);
    dBodyDisable(body_);
    dGeomDisable(reinterpret_cast<dGeomID>(space_));
  }
}

bool Hurdle::at_rest() const {
  const dReal* v = dBodyGetLinearVel(body_);
  const dReal* w = dBodyGetAngularVel(body_);
  return Eigen::Vector3d(v[0], v[1], v[2]).norm() < 0.02 &&
         Eigen::Vector3d(w[0], w[1], w[2]).norm() < 0.05;
}

Eigen::Vector3d Hurdle::position() const {
  const dReal* p = dBodyGetPosition(body_);
  return {p[0], p[1], p[2]};
}

Eigen::Quaterniond Hurdle::orientation() const {
  const dReal* q = dBodyGetQuaternion(body_);
  return {q[0], q[1], q[2], q[3]};
}

Eigen::Vector3d Hurdle::top_centre() const {
  return position() + orientation() * (Eigen::Vector3d(0, 0, height_) - com_);
}

bool Hurdle::knocked_over() const {
  return (orientation() * Eigen::Vector3d::UnitZ()).z() < std::cos(M_PI / 4);
}

}  // namespace olympics::sports::hurdles
