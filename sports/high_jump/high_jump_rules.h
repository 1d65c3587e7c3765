// The high jump's geometry and rules, as the seed has them ("paper") or World Athletics TR 26-27
// ("official"); high_jump_sport.cpp maps the settings onto them. x runs from the start mark
// toward the bar, y to the left; the bar lies along y.
#pragma once

#include <vector>

namespace olympics::sports::high_jump {

struct HighJumpRules {
  bool official = false;     // the official failures and clearance, else the seed's
  double bar_x = 20.0;       // m: the bar's plane (the seed: 20 m ahead)
  double bar_y = 6.0;        // m: the bar's centre (the seed: 6 m to the left)
  double upright_gap = 4.0;  // m between the supports' centres (TR 27.5: 4.00 to 4.04)
  // The crossbar: a free rigid body (the seed's: 8 kg, r 25 mm, 4.1 m on 0.1 m posts; TR 27.6:
  // <= 2 kg, 30 mm round, 4.00 m, on 40 x 60 mm supports).
  double bar_length = 4.1, bar_radius = 0.025, bar_mass = 8.0;
  double support_depth = 0.1, support_length = 0.1;  // m across (x) and along (y) the bar
  // Official: the run-up, a fan-shaped area in front of the bar (TR 27.3: a runway of at least
  // 15 m, 25 m at the major international competitions; the Facilities Manual draws it as a
  // semicircle round the bar's centre): here the half disc of this radius on the approach side
  // of the bar's plane, centred on the bar's centre on the ground. Leaving it before going over
  // is a failure (left_area). The seed's start mark is 20.9 m from the bar's centre.
  double runup_radius = 25.0;
  bool landing_mat = false;  // the 6 x 4 x 0.7 m soft mat behind the bar (TR 27.9); the seed: none
  std::vector<double> heights{1.0};  // m, the bar's top, in the order they are jumped
  int tries_per_height = 1;          // the seed's episode: 1; TR 26.4: 3
  // m the jump-off for first place (TR 26.9) raises or lowers the bar by; 0: no jump-off, a tie
  // after the countback shares first place (the paper rules)
  double jump_off_step = 0.0;
  double attempt_s = 20.0;               // s per attempt (TR 25.17: 1 minute)
  double settle_s = 1.5;                 // s on the landing area, bar still up, before a clearance
  double lane_spacing = 12.0;            // m between a competition's installations
  double goal_past = 2.0, goal_z = 1.0;  // the seed's goal: 2 m past the bar, 1 m up
};

}  // namespace olympics::sports::high_jump
