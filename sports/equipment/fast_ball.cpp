#include "equipment/fast_ball.h"

namespace olympics::sports::equipment {

bool FastBallGuard::before_step(core::PhysicsWorld& world, Ball& ball, double dt) {
  const Eigen::Vector3d p0 = ball.position(), v = ball.velocity();
  // A ball that moves less than a quarter of its radius cannot skip anything it could hit.
  if (v.norm() * dt < 0.25 * ball.spec().radius) return false;
  const int self = ball.entity();
  const auto touch =
      probe_.first_touch(world, p0, p0 + v * dt, [self](int entity, int) { return entity == self; },
                         {.arena = true, .refine = true});
  if (!touch || (touch->centre - p0).squaredNorm() < 1e-12) return false;
  ball.move_to(touch->centre);
  return true;
}

}  // namespace olympics::sports::equipment
