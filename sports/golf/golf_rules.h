// Golf's geometry and rules, as the seed has them ("paper") or the Rules of Golf ("official");
// golf_sport.cpp maps the settings onto them.
#pragma once

#include "golf/golf_club.h"

namespace olympics::sports::golf {

struct GolfRules {
  bool official = false;  // a hole to hole out in the fewest strokes, else the seed's task
  ClubSpec club = seed_club();
  // Official: the ball starts `distance` m from the hole, straight ahead (+x) in its lane.
  double distance = 2.0;
  double hole_radius = 0.054, hole_depth = 0.1016;
  double green_stimp = 3.05;    // m a ball rolls from 1.83 m/s on the green (stimp 10)
  double fairway_stimp = 1.52;  // and on the fairway (stimp 5)
  double green_radius = 6.0;    // m around the hole that is green; the rest is fairway
  // The green's slope (golf_green.h GreenSlope): `green_slope` percent, falling towards
  // `green_fall_deg` degrees counterclockwise from the line ball-to-hole (0: a downhill putt,
  // 90: the putt breaks left, 180: uphill). The fairway is flat.
  double green_slope = 0, green_fall_deg = 0;
  int max_strokes = 6;           // Rule 21.2: the committee's maximum score for the hole
  double hole_s = 60.0;          // s an athlete has to hole out (a picked-up ball scores max)
  double lane_half_width = 2.5;  // m either side of the line to the hole; beyond: out of bounds
  // Where a stroke is addressed from: the athlete is placed facing the hole with the ball
  // `address_side` m to its right and `address_ahead` m ahead of its root (a face-on putter).
  double address_side = 0.38, address_ahead = -0.17;
  // Whether the athlete is placed at address again after each stroke comes to rest (false: it
  // is placed for the first stroke only and walks to its ball for the others).
  bool placed_at_address = true;
  // Paper: the target `U(0, max_target)` m to the athlete's left of the ball (the seed's 0-20 m).
  double max_target = 20.0;
  double lane_spacing = 5.0;  // m between the athletes' lanes (paper: along x; official: along y)
};

}  // namespace olympics::sports::golf
