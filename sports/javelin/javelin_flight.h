// A javelin thrown alone, flown until it first touches the ground: to measure what the air does
// to its landing (tip first or not) apart from any athlete. Same physics as in a match: the
// scene's 120 Hz step, the world's ground contacts, the crossflow load when `aerodynamics`.
#pragma once

#include <Eigen/Core>

#include "javelin/javelin_rules.h"

namespace olympics::sports::javelin {

struct JavelinRelease {
  Eigen::Vector3d grip = {0, 0, 1.8};  // where the cord leaves the hand
  double speed = 25;                   // m/s
  double angle_deg = 35;               // of the velocity above the horizontal
  double attitude_deg = 35;            // of the javelin's axis above the horizontal
  double pitch_rate = 0;               // rad/s, positive tip up
};

struct JavelinLanding {
  bool landed = false;     // touched the ground within the time allowed
  bool tip_first = false;  // its first touch was by the head alone
  Eigen::Vector3d first_touch = Eigen::Vector3d::Zero();
  double t = 0;  // s of flight
};

JavelinLanding fly(const JavelinSpec& spec, bool aerodynamics, const JavelinRelease& release,
                   double max_s = 10.0);

}  // namespace olympics::sports::javelin
