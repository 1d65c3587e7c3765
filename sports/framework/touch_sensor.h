// A rule piece: scoring touches, from the contacts the physics world sensed in one step.
//
// A touch is a contact between a striking geom of one player (a sensor geom: a sword's tip, a
// glove) and a target body of a player of another team, with that contact's own normal force at
// or above a threshold. The floor, equipment, teammates and bodies outside the target set never
// count. One striking geom makes at most one touch per step (the strongest), and none while it
// keeps touching: a new touch needs `refractory_s` since its last qualifying contact (a glove
// pressed against a head is one punch, not one per step).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <map>
#include <tuple>
#include <vector>

#include "core/physics_world.h"

namespace olympics::sports {

struct Touch {
  int attacker = -1, defender = -1;          // slots
  int striker_body = -1, striker_geom = -1;  // the attacker's sensor geom
  int target_body = -1;                      // the defender's body that was hit
  double force = 0;                          // N, normal force of that contact
  double time = 0;                           // s, end of the physics step
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // from the target towards the striker
};

class TouchSensor {
 public:
  // Whether a geom (by body index and its index in the body's geoms) of a player is a target.
  using TargetTest = std::function<bool(int body, int geom)>;
  // slot_entities: each slot's humanoid entity.
  TouchSensor(std::vector<int> slot_entities, std::vector<int> slot_teams, TargetTest is_target,
              double min_force_n, double refractory_s);

  // The touches of the physics step that just ended at `time`.
  std::vector<Touch> collect(const core::PhysicsWorld& world, double time);
  // Forgets when each striker last touched (after play is reset).
  void reset() { last_touch_.clear(); }
  double min_force_n() const { return min_force_n_; }

 private:
  int slot_of(int entity) const;

  std::vector<int> slot_entities_, slot_teams_;
  TargetTest is_target_;
  double min_force_n_, refractory_s_;
  std::map<std::tuple<int, int, int>, double> last_touch_;  // (slot, body, geom) -> time
};

}  // namespace olympics::sports
