// The long jump's geometry and rules, as the seed has them ("paper") or World Athletics TR 29-30
// ("official"); long_jump_sport.cpp maps the settings onto them.
#pragma once

namespace olympics::sports::long_jump {

struct LongJumpRules {
  bool official = false;  // the official measure and fouls, else the seed's
  double line_x = 20.0;   // m from the start mark: the foul (take-off) line, the board's far edge
  double board_depth = 0.20;  // m, the take-off board before the line (TR 29.4)
  double runway_width = 1.0;  // m (the seed's 1; TR 29.3: 1.22)
  double pit_near = 1.0;      // m from the line to the pit's near end (TR 29.5: 1 to 3)
  double pit_length = 9.0;    // m (the line to the pit's far end >= 10 m)
  double pit_width = 2.75;    // m (TR 29.7: 2.75 to 3)
  int attempts = 1;           // per athlete (the seed's episode: 1; TR 25.5: 3 rounds)
  double attempt_s = 20.0;    // s an attempt may take before it counts as a failure (TR 25.17: 60)
  double settle_s = 1.0;      // s after the first break in the sand before the mark is taken
  double lane_spacing = 5.0;  // m between the runways of a competition's athletes
  // The seed's goal, from the start mark, 1 m above the ground.
  double goal_x = 30.0, goal_z = 1.0;

  double pit_start() const { return line_x + pit_near; }
  double pit_end() const { return pit_start() + pit_length; }
};

}  // namespace olympics::sports::long_jump
