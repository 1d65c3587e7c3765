// The hurdles race's geometry and rules, as the seed has them ("paper": SMPLOlympics' task and
// its hurdle.urdf) or World Athletics TR 16-19 and 22 ("official"); hurdles_sport.cpp maps the
// settings onto them. x runs from the start line toward the finish, y to the left; lane i's
// centre line is y = i * lane_width.
#pragma once

namespace olympics::sports::hurdles {

struct HurdlesRules {
  bool official = false;      // the official fouls and finish, else the seed's termination
  bool free_hurdles = false;  // hurdles that tip over (TR 22.3), else the seed's fixed walls
  // The race (the seed's and the men's 110 m; the women's 100 m: 100, 13.00, 8.50, 0.838).
  double race_m = 110.0;
  int hurdle_count = 10;
  double first_m = 13.72, spacing_m = 9.14;
  double hurdle_height = 1.067;  // m, the top of the top bar
  double lane_width = 1.22;      // m (TR 17.2: 1.22 +-0.01, the lines included)
  double lane_spacing =
      2.0;  // m between lanes' centre lines (the seed's agents: 2 m; official: 1.22)
  // An official hurdle (TR 22.3): 1.18-1.20 m wide, >= 10 kg, overturned by 3.6-4 kgf pushed
  // horizontally at the centre of the top bar's top edge.
  double hurdle_width = 1.20, hurdle_mass = 10.0, tip_force_kgf = 3.8;
  // The seed's hurdle: a fixed 0.05 x 2 x 2.134 m box centred on the ground (its top at 1.067).
  double wall_depth = 0.05, wall_width = 2.0;
  // The seed's termination: a non-foot body touching with more than 50 N, the root more than
  // 0.8 m off the lane's centre line, a fall.
  double touch_force_n = 50.0, track_half_width = 0.8;
  double start_x = 0.0;    // the root's start mark, +-0.1 m (the seed's: 0; official: -0.3,
                           // the feet behind the line)
  double get_up_s = 10.0;  // official: down this long in a row, the athlete did not finish
  double goal_z = 1.0;     // the seed's goal: the finish line's point 1 m up

  double hurdle_x(int i) const { return first_m + i * spacing_m; }
};

}  // namespace olympics::sports::hurdles
