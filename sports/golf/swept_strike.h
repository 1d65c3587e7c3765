// A fast club head against the ball, between physics steps. ODE collides only at the start of a
// step: a 40 m/s driver head moves 0.33 m in a 120 Hz step, and passes a ball 43 mm across that
// it met in the middle of the step. So after each step the head's box is swept from its pose at
// the step's start to its pose at the end against the ball (equipment::sweep_ball_box, exact
// conservative advancement; the head's path between the two poses is straight, its turn a slerp),
// and where it met the ball closing faster than the solver can hold (more than the ball's radius
// and the head's half depth in one step: 5.5 m/s for the driver, 4.4 m/s for the putter), the
// impact is resolved by club_impact: the ball leaves from where it was struck,
// flying on for the rest of the step, and the hand that holds the club takes the opposite
// impulse. Slower strikes (a putt) are the solver's own contacts, as before.
#pragma once

#include <ode/ode.h>

#include <optional>

#include "equipment/ball.h"
#include "equipment/swept_ball.h"
#include "golf/club_impact.h"
#include "golf/golf_club.h"

namespace olympics::sports::golf {

struct SweptStrike {
  double t = 0;                    // fraction of the step at which the head met the ball
  Eigen::Vector3d contact_centre;  // the ball's centre then
  Eigen::Vector3d normal;          // the face's, towards the ball
  ImpactResult impact;
};

// The head's pose for a hand at `hand` (its body origin's pose).
equipment::Pose club_head_pose(const ClubSpec& club, const equipment::Pose& hand);

// The strike of the head moving from head0 to head1 on the ball moving from ball0 to `ball`'s
// position over a step of dt, if it is one the solver cannot hold.
std::optional<SweptStrike> find_swept_strike(const ClubSpec& club, const equipment::Pose& head0,
                                             const equipment::Pose& head1,
                                             const Eigen::Vector3d& ball0,
                                             const equipment::Ball& ball, double dt);

// Sets the ball flying from the strike for the rest of the step and gives `hand` (the body
// holding the club) the opposite impulse at the contact point.
void apply_swept_strike(const SweptStrike& strike, equipment::Ball& ball, dBodyID hand, double dt);

}  // namespace olympics::sports::golf
