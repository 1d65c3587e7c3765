// A rule piece of boxing: which of a glove's contacts with the opponent are blows.
//
// Amateur boxing (AIBA Technical Rules) scores a blow landed "with the knuckle part of the closed
// glove" on the legal target "with the weight of the body or shoulder behind it"; a glove that is
// laid on, pushed or held there scores nothing. A contact force alone cannot tell the two apart:
// a 70 kg body leaning on a glove presses harder than most blows. So a glove's contacts with the
// legal target are grouped into episodes (the physics steps in a row in which it touches a
// target body of the opponent), and only an episode's arrival can score: the glove must close on
// the body it meets at a speed (the glove's velocity relative to that body at the contact point,
// along the contact normal, just before the step) and with its knuckle face (the face away from the
// wrist). An episode that goes on never scores again, however hard the glove presses or eases; a
// glove that leaves and comes back slowly does not score either.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "core/humanoid.h"
#include "core/physics_world.h"

namespace olympics::sports::boxing {

// Chosen on seeds 1-40 (docs/combat-sports.md), the scripted boxer's own arrivals on the target:
// its thrown punches (arm straight) arrived at 1.10 m/s or more in 5 of 6 (median 1.9), its
// guard gloves pressing on a head at 0.40 m/s median, 0.83 at the 99th percentile (n = 1605;
// 10 above 1.0). Every thrown one met the target within 46 degrees of the knuckle face's centre.
struct BlowRules {
  double min_closing_speed = 1.0;  // m/s, glove towards the body it meets, on arrival
  double knuckle_cone_cos = 0.5;   // the contact within 60 degrees of the knuckle face's centre
};

// The first physics step of a glove's contact with the opponent's target.
struct GloveArrival {
  int attacker = -1, hand = -1;  // slot; 0 left, 1 right
  int target_body = -1;          // the target body the glove met (its strongest contact)
  double time = 0;               // s, end of the physics step
  double force = 0;              // N, normal force of that contact in that step
  double closing_speed = 0;      // m/s, just before the step (> 0: closing)
  double knuckle_cos = 0;        // of the angle between the knuckle face's centre and the contact
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // from the target towards the glove
};

class BlowSensor {
 public:
  // Each slot's humanoid entity; its two hand bodies and the glove's centre in each hand's frame
  // (the hand body's origin is the wrist, so wrist -> centre points at the knuckles);
  // `is_target`, by body index: the bodies a blow must land on.
  BlowSensor(std::array<int, 2> slot_entities, std::array<int, 2> hands,
             std::array<Eigen::Vector3d, 2> glove_centres, std::vector<bool> is_target);

  // Before a physics step: every body of both boxers, to read the speeds blows arrive with.
  void before_step(std::array<std::vector<core::BodyState>, 2> states) {
    before_ = std::move(states);
  }
  // The arrivals of the physics step that just ended at `time` (at most one per glove).
  std::vector<GloveArrival> collect(const core::PhysicsWorld& world, double time);
  // Forgets which gloves are touching (after the boxers are put back in their corners).
  void reset() { touching_ = {}; }

 private:
  int slot_of(int entity) const;
  int hand_of(int body) const;
  GloveArrival arrival(const core::SensedContact& c, int attacker, int hand, double time) const;

  std::array<int, 2> slot_entities_, hands_;
  std::array<Eigen::Vector3d, 2> glove_centres_;
  std::vector<bool> is_target_;
  std::array<std::vector<core::BodyState>, 2> before_;
  std::array<std::array<bool, 2>, 2> touching_{};  // [slot][hand] in the step before
};

// Is this arrival a blow under `rules` (it scores if it also lands on the legal target)?
bool is_blow(const GloveArrival& a, const BlowRules& rules);

}  // namespace olympics::sports::boxing
