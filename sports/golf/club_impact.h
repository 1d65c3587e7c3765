// The club face striking the ball, resolved as one impulse (the ~0.5 ms of a real impact is far
// shorter than a physics step): the head is a free mass at impact (the shaft is too flexible to
// add the hands' mass in that time), so the normal impulse is (1 + e) times the pair's reduced
// mass times the closing speed along the face normal, e the club's coefficient of restitution;
// the ball slides up the lofted face and Coulomb friction (the face's) turns that into backspin,
// the impulse along the face never more than makes the ball roll on it (no slip at the contact).
// Loft enters through the face normal. Not modelled: the head's own rotation (gear effect of a
// strike off the face's centre), shaft bending, the ball's deformation.
#pragma once

#include <Eigen/Core>

namespace olympics::sports::golf {

struct ImpactBall {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d spin = Eigen::Vector3d::Zero();  // rad/s
  double mass = 0;                                 // kg
  double radius = 0;                               // m
  double inertia = 0;  // kg m^2 about its centre (2/5 m r^2 for a solid ball)
};

struct ImpactFace {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // of the face at the contact point
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();   // unit, from the face towards the ball
  double head_mass = 0;                                // kg
  double restitution = 0;
  double friction = 0;
};

struct ImpactResult {
  Eigen::Vector3d velocity;  // the ball's, after
  Eigen::Vector3d spin;
  Eigen::Vector3d impulse;  // on the ball (the head takes its opposite)
};

// The ball after the face strikes it; unchanged (impulse 0) if they are not closing.
ImpactResult club_impact(const ImpactBall& ball, const ImpactFace& face);

}  // namespace olympics::sports::golf
