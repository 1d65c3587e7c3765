// One official hurdle (TR 22.3): a free rigid body, the top bar on two uprights that stand on two
// bases reaching back toward the start, with counterweights on the bases placed so that a
// horizontal push of `tip_force_kgf` at the centre of the top bar's top edge overturns it
// forward. The counterweights' place follows from the statics: pushed with F at the height H it
// turns about the front edge of its bases when F H = M g d, d the centre of mass's distance
// behind that edge.
#pragma once

#include <ode/ode.h>

#include <Eigen/Geometry>
#include <vector>

#include "core/physics_world.h"
#include "hurdles/hurdles_rules.h"

namespace olympics::sports::hurdles {

// A box of the hurdle in its own frame: x toward the finish, y across the lane, z up, the origin
// on the ground under the top bar's centre.
struct HurdlePart {
  Eigen::Vector3d centre, half;
  double mass;
  bool collides;  // the counterweights are mass only (they sit inside the bases)
};

// The hurdle's parts for `rules` (its height, width, mass and tipping force).
std::vector<HurdlePart> hurdle_parts(const HurdlesRules& rules);
// The push (kgf) at the top bar's centre that overturns a hurdle of these parts: M d / H.
double tipping_force_kgf(const std::vector<HurdlePart>& parts, double height);

class Hurdle {
 public:
  // A hurdle standing with its top bar's centre above (x, y); its geoms go in a space of their
  // own inside `parent` (a lane's space; none: the world's).
  Hurdle(core::PhysicsWorld& world, const HurdlesRules& rules, double x, double y,
         dSpaceID parent = nullptr);
  Hurdle(const Hurdle&) = delete;
  Hurdle& operator=(const Hurdle&) = delete;

  dBodyID body() const { return body_; }
  // The top bar's centre (its top edge), where it stands or lies now.
  Eigen::Vector3d top_centre() const;
  Eigen::Vector3d position() const;  // the body's (its centre of mass)
  Eigen::Quaterniond orientation() const;
  // Tilted past 45 degrees from upright: knocked over.
  bool knocked_over() const;
  // Asleep, the hurdle is left out of the simulation (its body disabled, its geoms out of
  // collision): nothing can touch it, so it stays exactly as it lay. The match puts hurdles at
  // rest and far from every athlete to sleep (the race's 80 hurdles, at rest on 8 contact points
  // each, would otherwise cost the solver more than the 8 athletes).
  void set_awake(bool awake);
  bool awake() const { return awake_; }
  bool at_rest() const;
  // The parts' shapes in the body's frame (for viewers).
  const std::vector<HurdlePart>& parts() const { return parts_; }
  const Eigen::Vector3d& centre_of_mass() const { return com_; }  // in the hurdle's frame

 private:
  std::vector<HurdlePart> parts_;
  Eigen::Vector3d com_ = Eigen::Vector3d::Zero();
  double height_;
  dBodyID body_ = nullptr;
  dSpaceID space_ = nullptr;  // its geoms
  core::GeomTag tag_;
  bool awake_ = true;
};

}  // namespace olympics::sports::hurdles
