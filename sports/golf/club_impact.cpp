#include "golf/club_impact.h"

#include <Eigen/Geometry>
#include <algorithm>

namespace olympics::sports::golf {

ImpactResult club_impact(const ImpactBall& ball, const ImpactFace& face) {
  const Eigen::Vector3d& n = face.normal;
  const Eigen::Vector3d closing = ball.velocity - face.velocity;
  const double closing_n = closing.dot(n);
  if (closing_n >= 0) return {ball.velocity, ball.spin, Eigen::Vector3d::Zero()};
  const double reduced_mass = ball.mass * face.head_mass / (ball.mass + face.head_mass);
  const double normal_impulse = -(1 + face.restitution) * reduced_mass * closing_n;
  // The ball's contact point slides over the face at its tangential velocity plus its spin's.
  const Eigen::Vector3d lever = -ball.radius * n;  // ball centre -> contact point
  const Eigen::Vector3d slip =
      closing - closing_n * n + ball.spin.cross(lever) - (ball.spin.cross(lever)).dot(n) * n;
  Eigen::Vector3d impulse = normal_impulse * n;
  const double slip_speed = slip.norm();
  if (slip_speed > 0) {
    // Impulse along the face that stops the slip: the slip changes by it times 1/m + 1/M + r^2/I.
    const double to_roll =
        slip_speed / (1 / reduced_mass + ball.radius * ball.radius / ball.inertia);
    impulse -= std::min(face.friction * normal_impulse, to_roll) * slip / slip_speed;
  }
  return {ball.velocity + impulse / ball.mass, ball.spin + lever.cross(impulse) / ball.inertia,
          impulse};
}

}  // namespace olympics::sports::golf
