// One ODE world with a ground plane: the unit a match owns and steps on one thread.
//
// Geoms carry a GeomTag that says which entity (a humanoid, a ball, the arena) and which body
// they belong to; the world asks each entity's ContactFilter whether two of its own bodies may
// touch, and records which bodies touched the ground during the last step.
#pragma once

#include <ode/ode.h>

#include <cstdint>
#include <functional>
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

// Per-geom identity, stored as the geom's user data.
struct GeomTag {
  int entity = -1;  // -1: static arena
  int body = -1;    // body index inside the entity
  double friction = 1.0;
  double restitution = 0.0;
  // Set by PhysicsWorld::step when this geom touched the ground plane during the step.
  std::uint8_t* ground_touch = nullptr;
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

  // Collide, solve one QuickStep of dt seconds, drop the contacts.
  void step(double dt);
  int last_contact_count() const { return last_contact_count_; }
  // Contacts between two different entities (e.g. two humanoids) in the last step.
  int last_inter_entity_contact_count() const { return last_inter_entity_contacts_; }

 private:
  static void near_callback(void* self, dGeomID a, dGeomID b);
  void collide_pair(dGeomID a, dGeomID b);

  WorldSettings settings_;
  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contacts_ = nullptr;
  dGeomID ground_ = nullptr;
  dThreadingImplementationID threading_ = nullptr;
  std::vector<SelfCollisionFilter> entity_filters_;
  int last_contact_count_ = 0;
  int last_inter_entity_contacts_ = 0;
};

}  // namespace olympics::core
