#include "javelin/javelin_implement.h"

#include "javelin/javelin_aero.h"

namespace olympics::sports::javelin {
namespace {

// ODE's category bits: while held, the hand's geoms are in kHandBit and the javelin's in
// kJavelinBit, each side's collide bits leaving the other out (ODE collides a pair when
// (cat1 & col2) || (cat2 & col1)); every other geom keeps the default (all bits).
constexpr unsigned long kAllBits = ~0ul;
constexpr unsigned long kHandBit = 1ul << 20, kJavelinBit = 1ul << 21;

// A capsule along the body's x from `from_tip` to `to_tip` metres behind the tip.
dGeomID add_segment(dSpaceID space, dBodyID body, const JavelinSpec& spec, double from_tip,
                    double to_tip, double radius) {
  const double length = std::max(to_tip - from_tip - 2 * radius, 1e-3);
  dGeomID g = dCreateCapsule(space, radius, length);
  dGeomSetBody(g, body);
  const double centre = spec.tip_to_com - 0.5 * (from_tip + to_tip);
  dGeomSetOffsetPosition(g, centre, 0, 0);
  dMatrix3 r;
  dRFromAxisAndAngle(r, 0, 1, 0, M_PI / 2);  // the capsule's z onto the body's x
  dGeomSetOffsetRotation(g, r);
  return g;
}

}  // namespace

Javelin::Javelin(core::PhysicsWorld& world, const JavelinSpec& spec)
    : spec_(spec),
      world_(world.world()),
      body_(dBodyCreate(world.world())),
      head_tag_(std::make_unique<core::GeomTag>()),
      shaft_tag_(std::make_unique<core::GeomTag>()) {
  dMass m;
  const double axial = 0.5 * spec.mass * spec.radius * spec.radius;
  const double transverse = spec.transverse_inertia();
  dMassSetParameters(&m, spec.mass, 0, 0, 0, axial, transverse, transverse, 0, 0, 0);
  dBodySetMass(body_, &m);
  const int entity = world.add_entity([](int, int) { return false; });
  head_ = add_segment(world.space(), body_, spec, 0.0, spec.head_length, spec.head_radius);
  shaft_ = add_segment(world.space(), body_, spec, spec.head_length, spec.length, spec.radius);
  int index = 0;
  for (auto* tag : {head_tag_.get(), shaft_tag_.get()}) {
    tag->entity = entity;
    tag->body = 0;
    tag->geom = index++;
    tag->friction = 1.0;  // SMPLOlympics' javelin: friction 1
  }
  dGeomSetData(head_, head_tag_.get());
  dGeomSetData(shaft_, shaft_tag_.get());
  place(Eigen::Vector3d(0, 0, 1), Eigen::Quaterniond::Identity());
}

Javelin::~Javelin() {
  release();
  dGeomDestroy(head_);
  dGeomDestroy(shaft_);
  dBodyDestroy(body_);
}

Eigen::Vector3d Javelin::centre() const {
  const dReal* p = dBodyGetPosition(body_);
  return {p[0], p[1], p[2]};
}

Eigen::Quaterniond Javelin::orientation() const {
  const dReal* q = dBodyGetQuaternion(body_);
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
}

Eigen::Vector3d Javelin::velocity() const {
  const dReal* v = dBodyGetLinearVel(body_);
  return {v[0], v[1], v[2]};
}

Eigen::Vector3d Javelin::spin() const {
  const dReal* w = dBodyGetAngularVel(body_);
  return {w[0], w[1], w[2]};
}

void Javelin::place(const Eigen::Vector3d& grip, const Eigen::Quaterniond& q) {
  const Eigen::Vector3d centre =
      grip + (spec_.tip_to_grip - spec_.tip_to_com) * (q * Eigen::Vector3d::UnitX());
  dBodySetPosition(body_, centre.x(), centre.y(), centre.z());
  const dQuaternion dq = {q.w(), q.x(), q.y(), q.z()};
  dBodySetQuaternion(body_, dq);
  set_motion(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
}

void Javelin::set_motion(const Eigen::Vector3d& v, const Eigen::Vector3d& w) {
  dBodySetLinearVel(body_, v.x(), v.y(), v.z());
  dBodySetAngularVel(body_, w.x(), w.y(), w.z());
}

void Javelin::add_aerodynamic_load() {
  const AeroLoad load = crossflow_load(spec_, axis(), velocity(), spin());
  dBodyAddForce(body_, load.force.x(), load.force.y(), load.force.z());
  dBodyAddTorque(body_, load.torque.x(), load.torque.y(), load.torque.z());
}

void Javelin::set_hand_collisions(bool held) {
  for (dGeomID g : hand_) {
    dGeomSetCategoryBits(g, held ? kHandBit : kAllBits);
    dGeomSetCollideBits(g, held ? kAllBits & ~kJavelinBit : kAllBits);
  }
  for (dGeomID g : {head_, shaft_}) {
    dGeomSetCategoryBits(g, held ? kJavelinBit : kAllBits);
    dGeomSetCollideBits(g, held ? kAllBits & ~kHandBit : kAllBits);
  }
}

void Javelin::grip(dBodyID palm, const std::vector<dGeomID>& hand) {
  release();
  hand_ = hand;
  grip_ = dJointCreateFixed(world_, nullptr);
  dJointAttach(grip_, palm, body_);
  dJointSetFixed(grip_);
  set_hand_collisions(true);
}

void Javelin::release() {
  if (!grip_) return;
  dJointDestroy(grip_);
  grip_ = nullptr;
  set_hand_collisions(false);
  hand_.clear();
}

}  // namespace olympics::sports::javelin
