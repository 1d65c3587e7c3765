// Continuous collision for a fast ODE ball (a kicked soccer ball): ODE collides only at the start
// of a step, and a 35 m/s ball moves 0.29 m per 120 Hz step, more than a post, a crossbar or a
// foot is thick. Before each physics step the guard sweeps the ball's path over the step
// (BodyProbe, the arena included, the ground plane not); if the ball would meet a geom, it moves
// the ball along its path to where it first overlaps that geom (by under a millimetre), so the
// step's collision finds the contact and the solver bounces the ball off it. The ball reaches
// what it hits up to one step early; its path and velocity are kept.
#pragma once

#include "equipment/ball.h"
#include "equipment/body_probe.h"

namespace olympics::sports::equipment {

class FastBallGuard {
 public:
  explicit FastBallGuard(double ball_radius) : probe_(ball_radius) {}

  // Call before every physics step of `dt` (after the ball's forces are set). Returns whether
  // the ball was moved to a contact.
  bool before_step(core::PhysicsWorld& world, Ball& ball, double dt);

 private:
  BodyProbe probe_;
};

}  // namespace olympics::sports::equipment
