#include "core/physics_world.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

#include "core/ode_runtime.h"

namespace olympics::core {

PhysicsWorld::PhysicsWorld(const WorldSettings& settings) : settings_(settings) {
  ensure_ode_ready_for_this_thread();
  world_ = dWorldCreate();
  dWorldSetGravity(world_, 0, 0, settings_.gravity);
  dWorldSetERP(world_, settings_.erp);
  dWorldSetCFM(world_, settings_.cfm);
  dWorldSetQuickStepNumIterations(world_, settings_.solver_iterations);
  dWorldSetContactMaxCorrectingVel(world_, settings_.max_correcting_velocity);
  dWorldSetContactSurfaceLayer(world_, settings_.contact_surface_layer);
  dWorldSetAutoDisableFlag(world_, 0);
  // A self-threaded implementation per world keeps worlds on different threads independent.
  threading_ = dThreadingAllocateSelfThreadedImplementation();
  dWorldSetStepThreadingImplementation(world_, dThreadingImplementationGetFunctions(threading_),
                                       threading_);
  // A simple space tests every pair's bounding boxes: with ~50 geoms per match that is cheaper
  // than hashing (callgrind, 10 s of a 1v1: 14% fewer instructions than dHashSpace).
  space_ = dSimpleSpaceCreate(nullptr);
  contacts_ = dJointGroupCreate(0);
  ground_ = dCreatePlane(space_, 0, 0, 1, 0);
}

PhysicsWorld::~PhysicsWorld() {
  ensure_ode_ready_for_this_thread();
  dJointGroupDestroy(contacts_);
  dSpaceDestroy(space_);  // destroys the geoms it holds
  dWorldSetStepThreadingImplementation(world_, nullptr, nullptr);
  dThreadingFreeImplementation(threading_);
  dWorldDestroy(world_);
}

int PhysicsWorld::add_entity(SelfCollisionFilter filter) {
  entity_filters_.push_back(std::move(filter));
  return static_cast<int>(entity_filters_.size()) - 1;
}

namespace {

GeomTag* arena_tag(std::vector<std::unique_ptr<GeomTag>>& tags, double friction,
                   double restitution) {
  auto tag = std::make_unique<GeomTag>();
  tag->friction = friction;
  tag->restitution = restitution;
  tags.push_back(std::move(tag));
  return tags.back().get();
}

// The softness a pair's contacts take: the softer of the two geoms' own, if either has one.
const ContactSoftness* softer_surface(const GeomTag* a, const GeomTag* b) {
  const ContactSoftness* soft_a = a && a->softness ? &*a->softness : nullptr;
  const ContactSoftness* soft_b = b && b->softness ? &*b->softness : nullptr;
  if (!soft_a) return soft_b;
  if (!soft_b) return soft_a;
  return soft_b->stiffness < soft_a->stiffness ? soft_b : soft_a;
}

}  // namespace

dGeomID PhysicsWorld::add_static_capsule(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                         double radius, double friction, double restitution) {
  const Eigen::Vector3d axis = b - a;
  dGeomID g = dCreateCapsule(space_, radius, axis.norm());
  const Eigen::Vector3d centre = 0.5 * (a + b);
  dGeomSetPosition(g, centre.x(), centre.y(), centre.z());
  // A capsule lies along its local z.
  const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis);
  const dQuaternion oq = {q.w(), q.x(), q.y(), q.z()};
  dGeomSetQuaternion(g, oq);
  dGeomSetData(g, arena_tag(static_tags_, friction, restitution));
  return g;
}

dGeomID PhysicsWorld::add_static_box(const Eigen::Vector3d& centre, const Eigen::Vector3d& half,
                                     double friction, double restitution) {
  dGeomID g = dCreateBox(space_, 2 * half.x(), 2 * half.y(), 2 * half.z());
  dGeomSetPosition(g, centre.x(), centre.y(), centre.z());
  dGeomSetData(g, arena_tag(static_tags_, friction, restitution));
  return g;
}

void PhysicsWorld::step(double dt) {
  ensure_ode_ready_for_this_thread();
  last_contact_count_ = 0;
  last_inter_entity_contacts_ = 0;
  feedback_.clear();
  feedback_normals_.clear();
  pending_.clear();
  ground_contacts_.clear();
  step_dt_ = dt;
  dSpaceCollide(space_, this, &PhysicsWorld::near_callback);
  dWorldQuickStep(world_, dt);
  measure_sensed_forces();
  dJointGroupEmpty(contacts_);
}

// ODE's contact normal points from the second geom towards the first; the joint's feedback holds
// the force on its first attached body, whose component along the normal is the contact's normal
// force (its sign depends on which body ODE attached first, so the magnitude is taken).
void PhysicsWorld::measure_sensed_forces() {
  sensed_.clear();
  for (auto& p : pending_) {
    SensedContact c = p.contact;
    c.normal_force = 0;
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    for (int i = 0; i < p.count; ++i) {
      const dJointFeedback& fb = feedback_[p.first_feedback + i];
      const Eigen::Vector3d& n = feedback_normals_[p.first_feedback + i];
      c.normal_force += std::abs(Eigen::Vector3d(fb.f1[0], fb.f1[1], fb.f1[2]).dot(n));
      normal += n;
    }
    c.normal = (p.sensor_is_first ? 1.0 : -1.0) * normal.normalized();
    sensed_.push_back(c);
  }
}

void PhysicsWorld::record_ground_contact(const GeomTag* tag, const dContactGeom* points,
                                         int count) {
  for (int i = 0; i < count; ++i)
    ground_contacts_.push_back({tag, {points[i].pos[0], points[i].pos[1], points[i].pos[2]}});
}

void PhysicsWorld::near_callback(void* self, dGeomID a, dGeomID b) {
  // A space inside the world's (the geoms of one piece of equipment, so that the broad phase
  // tests the piece once against the rest): collide what it holds.
  if (dGeomIsSpace(a) || dGeomIsSpace(b)) {
    dSpaceCollide2(a, b, self, &PhysicsWorld::near_callback);
    return;
  }
  static_cast<PhysicsWorld*>(self)->collide_pair(a, b);
}

void PhysicsWorld::collide_pair(dGeomID a, dGeomID b) {
  dBodyID body_a = dGeomGetBody(a), body_b = dGeomGetBody(b);
  if (!body_a && !body_b) return;
  if (body_a && body_b && dAreConnectedExcluding(body_a, body_b, dJointTypeContact)) return;
  auto* tag_a = static_cast<GeomTag*>(dGeomGetData(a));
  auto* tag_b = static_cast<GeomTag*>(dGeomGetData(b));
  if (tag_a && tag_b && tag_a->entity >= 0 && tag_a->entity == tag_b->entity &&
      !entity_filters_[tag_a->entity](tag_a->body, tag_b->body))
    return;

  if ((a == ground_ && tag_b && tag_b->passes_ground) ||
      (b == ground_ && tag_a && tag_a->passes_ground))
    return;

  std::array<dContactGeom, 8> found;
  int max = std::min<int>(settings_.max_contacts_per_pair, static_cast<int>(found.size()));
  int n = dCollide(a, b, max, found.data(), sizeof(dContactGeom));
  if (n == 0) return;

  bool a_ground = a == ground_, b_ground = b == ground_;
  double friction_a = a_ground ? settings_.ground_friction : (tag_a ? tag_a->friction : 1.0);
  double friction_b = b_ground ? settings_.ground_friction : (tag_b ? tag_b->friction : 1.0);
  double rest_a = a_ground ? settings_.ground_restitution : (tag_a ? tag_a->restitution : 0.0);
  double rest_b = b_ground ? settings_.ground_restitution : (tag_b ? tag_b->restitution : 0.0);
  if (a_ground && tag_b && tag_b->ground_touch) *tag_b->ground_touch = 1;
  if (b_ground && tag_a && tag_a->ground_touch) *tag_a->ground_touch = 1;
  if ((a_ground && tag_b) || (b_ground && tag_a))
    record_ground_contact(a_ground ? tag_b : tag_a, found.data(), n);

  dContact contact{};
  // MuJoCo's rule for pairs: the larger friction wins; restitution likewise.
  contact.surface.mu = std::max(friction_a, friction_b);
  contact.surface.mode = dContactApprox1 | dContactSoftERP | dContactSoftCFM;
  contact.surface.soft_erp = settings_.contact_erp;
  contact.surface.soft_cfm = settings_.contact_cfm;
  if (const ContactSoftness* soft = softer_surface(tag_a, tag_b)) {
    contact.surface.soft_erp = soft->erp(step_dt_);
    contact.surface.soft_cfm = soft->cfm(step_dt_);
  }
  double restitution = std::max(rest_a, rest_b);
  if (tag_a && tag_a->absorbs) restitution = rest_a;
  if (tag_b && tag_b->absorbs) restitution = rest_b;
  if (restitution > 0) {
    contact.surface.mode |= dContactBounce;
    contact.surface.bounce = restitution;
    contact.surface.bounce_vel = 0.2;  // PhysX's bounce threshold
  }
  const bool sensed = (tag_a && tag_a->sensor) || (tag_b && tag_b->sensor);
  const size_t first_feedback = feedback_.size();
  for (int i = 0; i < n; ++i) {
    contact.geom = found[i];
    dJointID j = dJointCreateContact(world_, contacts_, &contact);
    dJointAttach(j, body_a, body_b);
    if (sensed) {
      dJointSetFeedback(j, &feedback_.emplace_back());
      feedback_normals_.emplace_back(found[i].normal[0], found[i].normal[1], found[i].normal[2]);
    }
  }
  if (sensed) {
    SensedContact c;
    // where the pair touched: the mean of its points
    for (int i = 0; i < n; ++i)
      c.position += Eigen::Vector3d(found[i].pos[0], found[i].pos[1], found[i].pos[2]) / n;
    if (tag_a && tag_a->sensor) {
      c.sensor = tag_a, c.other = b_ground ? nullptr : tag_b;
      pending_.push_back({c, true, first_feedback, n});
    }
    if (tag_b && tag_b->sensor) {
      c.sensor = tag_b, c.other = a_ground ? nullptr : tag_a;
      pending_.push_back({c, false, first_feedback, n});
    }
  }
  last_contact_count_ += n;
  if (tag_a && tag_b && tag_a->entity >= 0 && tag_b->entity >= 0 && tag_a->entity != tag_b->entity)
    last_inter_entity_contacts_ += n;
}

}  // namespace olympics::core
