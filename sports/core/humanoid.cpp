#include "core/humanoid.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "core/body_mass.h"
#include "core/rotation.h"

namespace olympics::core {
namespace {

struct Transform {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  Transform operator*(const Transform& o) const { return {p + q * o.p, q * o.q}; }
  Eigen::Vector3d operator*(const Eigen::Vector3d& v) const { return p + q * v; }
};

// Rest-pose transforms of every body relative to the root body frame.
std::vector<Transform> rest_transforms(const ModelSpec& spec) {
  std::vector<Transform> out(spec.bodies.size());
  for (size_t i = 1; i < spec.bodies.size(); ++i) {
    const BodySpec& b = spec.bodies[i];
    out[i] = out[b.parent] * Transform{b.pos, b.quat};
  }
  return out;
}

dGeomID create_geom(dSpaceID space, const GeomSpec& g) {
  switch (g.shape) {
    case GeomShape::Sphere:
      return dCreateSphere(space, g.radius);
    case GeomShape::Capsule:
      return dCreateCapsule(space, g.radius, 2 * g.half_length);
    case GeomShape::Cylinder:
      return dCreateCylinder(space, g.radius, 2 * g.half_length);
    case GeomShape::Box:
      return dCreateBox(space, 2 * g.half_extents.x(), 2 * g.half_extents.y(),
                        2 * g.half_extents.z());
  }
  return nullptr;
}

// Vertical half-extent of a geom placed at transform t, and its centre height.
std::pair<double, double> geom_z_centre_and_extent(const GeomSpec& g, const Transform& body) {
  Transform t = body * Transform{g.pos, g.quat};
  Eigen::Vector3d axis = t.q * Eigen::Vector3d::UnitZ();
  double extent = 0;
  switch (g.shape) {
    case GeomShape::Sphere:
      extent = g.radius;
      break;
    case GeomShape::Capsule:
      extent = std::abs(axis.z()) * g.half_length + g.radius;
      break;
    case GeomShape::Cylinder:
      extent = std::abs(axis.z()) * g.half_length +
               g.radius * std::sqrt(std::max(0.0, 1 - axis.z() * axis.z()));
      break;
    case GeomShape::Box: {
      Eigen::Matrix3d r = t.q.toRotationMatrix();
      for (int k = 0; k < 3; ++k) extent += std::abs(r(2, k)) * g.half_extents[k];
      break;
    }
  }
  return {t.p.z(), extent};
}

}  // namespace

Humanoid::Humanoid(PhysicsWorld& world, const ModelSpec& spec, const RootPlacement& placement)
    : world_(world), spec_(spec), dof_count_(spec.dof_count()) {
  const int n = body_count();
  if (n == 0) throw std::invalid_argument(spec.source + ": the humanoid has no bodies");
  self_collision_allowed_.assign(n * n, 1);
  for (int i = 0; i < n; ++i) {
    self_collision_allowed_[i * n + i] = 0;
    if (int p = spec_.bodies[i].parent; p >= 0)
      self_collision_allowed_[i * n + p] = self_collision_allowed_[p * n + i] = 0;
  }
  for (auto [a, b] : spec_.contact_excludes)
    self_collision_allowed_[a * n + b] = self_collision_allowed_[b * n + a] = 0;
  entity_ = world_.add_entity([this](int a, int b) { return may_self_collide(a, b); });

  ground_touch_.assign(n, 0);
  auto rest = rest_transforms(spec_);
  double lowest = std::numeric_limits<double>::infinity();
  double highest = -lowest;
  for (int i = 0; i < n; ++i) {
    const BodySpec& b = spec_.bodies[i];
    if (b.geoms.empty())
      throw std::invalid_argument(spec_.source + ": body \"" + b.name +
                                  "\" has no geom, so it has no mass; give it one");
    dMass total = body_mass(b);
    for (const auto& g : b.geoms) {
      auto [centre, extent] = geom_z_centre_and_extent(g, rest[i]);
      lowest = std::min(lowest, centre - extent);
      highest = std::max(highest, centre + extent);
    }
    total_mass_ += total.mass;
    Eigen::Vector3d com(total.c[0], total.c[1], total.c[2]);
    dMassTranslate(&total, -com.x(), -com.y(), -com.z());
    // Joint armature (rotor inertia on each hinge) added as isotropic inertia of the child.
    double armature = 0;
    for (const auto& h : b.hinges) armature = std::max(armature, h.armature);
    for (int k = 0; k < 3; ++k) total.I[k * 4 + k] += armature;

    dBodyID body = dBodyCreate(world_.world());
    dBodySetMass(body, &total);
    bodies_.push_back(body);
    com_offset_.push_back(com);

    for (size_t k = 0; k < b.geoms.size(); ++k) {
      const GeomSpec& g = b.geoms[k];
      if (!g.collides) continue;
      dGeomID geom = create_geom(world_.space(), g);
      dGeomSetBody(geom, body);
      Eigen::Vector3d offset = g.pos - com;
      dGeomSetOffsetPosition(geom, offset.x(), offset.y(), offset.z());
      dQuaternion q = {g.quat.w(), g.quat.x(), g.quat.y(), g.quat.z()};
      dGeomSetOffsetQuaternion(geom, q);
      auto tag = std::make_unique<GeomTag>();
      tag->entity = entity_;
      tag->body = i;
      tag->geom = static_cast<int>(k);
      tag->sensor = g.sensor;
      tag->friction = g.friction;
      tag->ground_touch = &ground_touch_[i];
      dGeomSetData(geom, tag.get());
      tags_.push_back(std::move(tag));
    }
  }
  standing_root_height_ = -lowest + 0.002;
  rest_height_ = highest - lowest;

  // Joints are created in the rest pose at the placement, so anchors and motor axes are right.
  place_bodies(placement);
  drives_.resize(n);
  for (int i = 1; i < n; ++i) {
    const BodySpec& b = spec_.bodies[i];
    BodyState s = body_state(i);
    if (b.hinges.empty()) {
      dJointID weld = dJointCreateFixed(world_.world(), nullptr);
      dJointAttach(weld, bodies_[b.parent], bodies_[i]);
      dJointSetFixed(weld);
      welds_.push_back(weld);
    } else {
      drives_[i] = std::make_unique<JointDrive>(world_.world(), bodies_[b.parent], bodies_[i],
                                                s.position, b);
    }
  }
}

Humanoid::~Humanoid() {
  // Geoms belong to the world's space and are destroyed with it; bodies and joints likewise.
  // A humanoid is never destroyed before its world in this project.
}

bool Humanoid::may_self_collide(int a, int b) const {
  return self_collision_allowed_[a * body_count() + b] != 0;
}

void Humanoid::place_bodies(const RootPlacement& placement) {
  Eigen::Vector3d root_pos = placement.position;
  if (root_pos.z() <= 0) root_pos.z() = standing_root_height_;
  Transform root{root_pos,
                 Eigen::Quaterniond(Eigen::AngleAxisd(placement.yaw, Eigen::Vector3d::UnitZ()))};
  auto rest = rest_transforms(spec_);
  for (int i = 0; i < body_count(); ++i) {
    Transform t = root * rest[i];
    Eigen::Vector3d com = t * com_offset_[i];
    dBodySetPosition(bodies_[i], com.x(), com.y(), com.z());
    dQuaternion q = {t.q.w(), t.q.x(), t.q.y(), t.q.z()};
    dBodySetQuaternion(bodies_[i], q);
    dBodySetLinearVel(bodies_[i], 0, 0, 0);
    dBodySetAngularVel(bodies_[i], 0, 0, 0);
    dBodySetForce(bodies_[i], 0, 0, 0);
    dBodySetTorque(bodies_[i], 0, 0, 0);
  }
}

void Humanoid::reset(const RootPlacement& placement) {
  place_bodies(placement);
  std::vector<double> zeros(dof_count_, 0.0);
  set_joint_targets(zeros);
  clear_ground_contacts();
}

void Humanoid::set_joint_targets(std::span<const double> angles) {
  if (static_cast<int>(angles.size()) != dof_count_)
    throw std::invalid_argument("set_joint_targets: expected " + std::to_string(dof_count_) +
                                " angles, got " + std::to_string(angles.size()));
  size_t k = 0;
  for (int i = 0; i < body_count(); ++i) {
    size_t hinges = spec_.bodies[i].hinges.size();
    if (drives_[i]) drives_[i]->set_targets(angles.data() + k);
    k += hinges;
  }
}

void Humanoid::prepare_step(double h) {
  for (auto& d : drives_)
    if (d) d->prepare_step(h);
}

BodyState Humanoid::body_state(int i) const {
  dBodyID b = bodies_[i];
  BodyState s;
  s.orientation = from_ode_quat(dBodyGetQuaternion(b));
  const dReal* p = dBodyGetPosition(b);
  const dReal* v = dBodyGetLinearVel(b);
  const dReal* w = dBodyGetAngularVel(b);
  Eigen::Vector3d com(p[0], p[1], p[2]);
  Eigen::Vector3d lever = -(s.orientation * com_offset_[i]);  // com -> origin
  s.position = com + lever;
  s.angular_velocity = Eigen::Vector3d(w[0], w[1], w[2]);
  s.linear_velocity = Eigen::Vector3d(v[0], v[1], v[2]) + s.angular_velocity.cross(lever);
  return s;
}

std::vector<BodyState> Humanoid::body_states() const {
  std::vector<BodyState> out;
  out.reserve(bodies_.size());
  for (int i = 0; i < body_count(); ++i) out.push_back(body_state(i));
  return out;
}

void Humanoid::clear_ground_contacts() { std::fill(ground_touch_.begin(), ground_touch_.end(), 0); }

}  // namespace olympics::core
