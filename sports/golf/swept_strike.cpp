#include "golf/swept_strike.h"

#include <Eigen/Geometry>

namespace olympics::sports::golf {

equipment::Pose club_head_pose(const ClubSpec& club, const equipment::Pose& hand) {
  return {hand.position + hand.orientation * club_head_offset(club),
          hand.orientation * club_head_orientation(club)};
}

std::optional<SweptStrike> find_swept_strike(const ClubSpec& club, const equipment::Pose& head0,
                                             const equipment::Pose& head1,
                                             const Eigen::Vector3d& ball0,
                                             const equipment::Ball& ball, double dt) {
  const double r = ball.spec().radius;
  const auto hit =
      equipment::sweep_ball_box(ball0, ball.position(), r, {club.head_half}, head0, head1, dt);
  if (!hit) return std::nullopt;
  const double closing = -(ball.velocity() - hit->surface_point_velocity).dot(hit->normal);
  // Closing less than the ball's radius and the head's half depth in a step, the ball's centre
  // cannot pass the head's middle: the solver's contact at the next step's start pushes it out
  // of the face. Faster, the head can pass it or push it out of its back.
  if (closing * dt <= r + club.head_half.x()) return std::nullopt;
  dMass m;
  dBodyGetMass(ball.body(), &m);
  const ImpactBall before{ball.velocity(), ball.angular_velocity(), ball.spec().mass, r, m.I[0]};
  const ImpactFace face{hit->surface_point_velocity, hit->normal, club.head_mass, club.restitution,
                        club.friction};
  return SweptStrike{hit->t, hit->ball_centre, hit->normal, club_impact(before, face)};
}

void apply_swept_strike(const SweptStrike& strike, equipment::Ball& ball, dBodyID hand, double dt) {
  const ImpactResult& i = strike.impact;
  ball.set_state(strike.contact_centre + (1 - strike.t) * dt * i.velocity, i.velocity, i.spin);
  // The hand's share: -J at the contact point, as a change of its velocity and spin (its joints
  // pass it on to the arm in the next step).
  dMass m;
  dBodyGetMass(hand, &m);
  const dReal* p = dBodyGetPosition(hand);
  const dReal* v = dBodyGetLinearVel(hand);
  const dReal* w = dBodyGetAngularVel(hand);
  const dReal* q = dBodyGetQuaternion(hand);
  const Eigen::Matrix3d rot = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix();
  Eigen::Matrix3d inertia_body;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) inertia_body(r, c) = m.I[r * 4 + c];
  const Eigen::Matrix3d inertia = rot * inertia_body * rot.transpose();
  const Eigen::Vector3d impulse = -i.impulse;
  const Eigen::Vector3d contact = strike.contact_centre - ball.spec().radius * strike.normal;
  const Eigen::Vector3d lever = contact - Eigen::Vector3d(p[0], p[1], p[2]);
  const Eigen::Vector3d dv = impulse / m.mass;
  const Eigen::Vector3d dw = inertia.inverse() * lever.cross(impulse);
  dBodySetLinearVel(hand, v[0] + dv.x(), v[1] + dv.y(), v[2] + dv.z());
  dBodySetAngularVel(hand, w[0] + dw.x(), w[1] + dw.y(), w[2] + dw.z());
}

}  // namespace olympics::sports::golf
