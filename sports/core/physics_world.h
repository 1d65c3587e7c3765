// One ODE world with a ground plane: the unit a match owns and steps on one thread.
//
// Geoms carry a GeomTag that says which entity (a humanoid, a ball, the arena) and which body
// they belong to; the world asks each entity's ContactFilter whether two of its own bodies may
// touch, and records which bodies touched the ground during the last step. Contacts of sensor
// geoms (a sword's tip, a glove) are reported after each step with the normal force the solver
// applied to that very contact (ODE joint feedback), not a body's total force.
#pragma once

#include <ode/ode.h>

#include <Eigen/Core>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace olympics::core {

struct WorldSettings {
  double gravity = -9.81;
  int solver_iterations = 8;  // QuickStep; above 8 ODE reorders rows with a global RNG
  double erp = 0.2;
  double cfm = 1e-7;
  double contact_erp = 0.2;
  double contact_cfm = 1e-6;
  double ground_friction = 1.0;
  double ground_restitution = 0.0;
  double max_correcting_velocity = 10.0;  // m/s, like PhysX's max depenetration velocity
  double contact_surface_layer = 0.001;
  int max_contacts_per_pair = 4;
};

// How a surface gives under a contact (a landing mat, a sand pit): a spring and a damper per
// contact point. Contacts with a geom that declares one use it instead of the world's
// contact_erp/contact_cfm; ODE's soft ERP and CFM for a step follow from the spring-damper and
// the step's length (ODE manual, "How to use ERP and CFM": erp = h k / (h k + c),
// cfm = 1 / (h k + c)).
struct ContactSoftness {
  double stiffness = 0;  // N/m per contact point
  double damping = 0;    // N s/m per contact point
  double erp(double dt) const { return dt * stiffness / (dt * stiffness + damping); }
  double cfm(double dt) const { return 1.0 / (dt * stiffness + damping); }
};

// Per-geom identity, stored as the geom's user data.
struct GeomTag {
  int entity = -1;      // -1: static arena
  int body = -1;        // body index inside the entity
  int geom = -1;        // index of the geom in its body's list (GeomSpec order)
  bool sensor = false;  // report this geom's contacts with their forces (sensed_contacts())
  double friction = 1.0;
  double restitution = 0.0;
  // This geom's restitution, not the larger of the pair's, holds for its contacts: a net or
  // padding swallows the bounce of a lively ball.
  bool absorbs = false;
  // This geom's own give (a mat, sand); none: the world's contact_erp/contact_cfm. When both
  // geoms of a pair declare one, the softer (lower stiffness) holds: the mat yields, not the foot.
  std::optional<ContactSoftness> softness;
  // The ground plane does not hold this geom (a golf ball over the hole falls through the plane
  // onto the cup's lip and into it). Off by default: no effect on any other geom.
  bool passes_ground = false;
  // Set by PhysicsWorld::step when this geom touched the ground plane during the step.
  std::uint8_t* ground_touch = nullptr;
};

// A contact of a sensor geom with another geom during the last step.
struct SensedContact {
  const GeomTag* sensor = nullptr;
  const GeomTag* other = nullptr;  // nullptr: the ground plane or an untagged static geom
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // mean of the pair's contact points
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();    // unit, from the other geom to the sensor
  double normal_force = 0;                             // N, summed over the pair's contact points
};

// A contact point of a tagged geom with the ground plane during the last step.
struct GroundContact {
  const GeomTag* geom = nullptr;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

class PhysicsWorld {
 public:
  explicit PhysicsWorld(const WorldSettings& settings = {});
  ~PhysicsWorld();
  PhysicsWorld(const PhysicsWorld&) = delete;
  PhysicsWorld& operator=(const PhysicsWorld&) = delete;

  dWorldID world() const { return world_; }
  dSpaceID space() const { return space_; }
  const WorldSettings& settings() const { return settings_; }

  // Whether two bodies of one entity may collide (adjacent links overlap by design).
  using SelfCollisionFilter = std::function<bool(int body_a, int body_b)>;
  int add_entity(SelfCollisionFilter filter);

  // Arena geometry that does not move (ropes, posts, goals): a capsule from `a` to `b`, a box
  // at `centre` with half-extents `half` (axis-aligned). Tagged as the arena (entity -1).
  dGeomID add_static_capsule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius,
                             double friction, double restitution);
  dGeomID add_static_box(const Eigen::Vector3d& centre, const Eigen::Vector3d& half,
                         double friction, double restitution);

  // The tag of a geom this world made or a humanoid tagged (its user data): to make a static
  // geom soft (`softness`) or a sensor after adding it.
  static GeomTag& tag_of(dGeomID geom) { return *static_cast<GeomTag*>(dGeomGetData(geom)); }

  // Collide, solve one QuickStep of dt seconds, drop the contacts.
  void step(double dt);
  int last_contact_count() const { return last_contact_count_; }
  // Contacts between two different entities (e.g. two humanoids) in the last step.
  int last_inter_entity_contact_count() const { return last_inter_entity_contacts_; }
  // Every contact pair of a sensor geom in the last step (a pair of two sensors: once from each).
  const std::vector<SensedContact>& sensed_contacts() const { return sensed_; }
  // Every tagged geom's contact with the ground plane in the last step, where it touched (a
  // foot beyond a foul line), unlike GeomTag::ground_touch, which a tick accumulates.
  const std::vector<GroundContact>& ground_contacts() const { return ground_contacts_; }

 private:
  static void near_callback(void* self, dGeomID a, dGeomID b);
  void collide_pair(dGeomID a, dGeomID b);
  void sense(const GeomTag* sensor, const GeomTag* other, bool sensor_is_first,
             const dContactGeom* points, int count);
  void measure_sensed_forces();
  void record_ground_contact(const GeomTag* tag, const dContactGeom* points, int count);

  // A sensed pair waiting for the solver: its contacts' feedback slots.
  struct PendingSense {
    SensedContact contact;
    bool sensor_is_first;  // the sensor is the contact's first geom (the normal points to it)
    size_t first_feedback;
    int count;
  };

  WorldSettings settings_;
  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contacts_ = nullptr;
  dGeomID ground_ = nullptr;
  dThreadingImplementationID threading_ = nullptr;
  std::vector<SelfCollisionFilter> entity_filters_;
  std::vector<std::unique_ptr<GeomTag>> static_tags_;
  double step_dt_ = 0;  // the step being collided: soft contacts' ERP and CFM depend on it
  int last_contact_count_ = 0;
  int last_inter_entity_contacts_ = 0;
  std::deque<dJointFeedback> feedback_;  // deque: ODE keeps pointers to its elements
  std::vector<Eigen::Vector3d> feedback_normals_;
  std::vector<PendingSense> pending_;
  std::vector<SensedContact> sensed_;
  std::vector<GroundContact> ground_contacts_;
};

}  // namespace olympics::core
