// What differs between tennis and table tennis, as data: the court or table, the ball, the
// equipment, where players stand, how balls are launched and where returns should land.
//
// Frame: the net lies along the y axis at x = 0; team 0 plays from the -x half, team 1 from +x.
// All heights are world heights (the ground is z = 0).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "equipment/ball.h"
#include "equipment/ball_flight.h"
#include "equipment/equipment.h"

namespace olympics::sports::racket {

enum ArenaSurface { kGround = 0, kNet = 1, kTable = 2 };

struct RacketGame {
  std::string sport;
  bool on_table = false;  // table tennis: balls must bounce on the table, the floor is out
  equipment::BallSpec ball;
  equipment::EquipmentSpec equipment;
  double half_length = 0;                                 // baseline / table end, |x|
  double half_width_singles = 0, half_width_doubles = 0;  // sidelines, |y|
  double surface_height = 0;  // where a ball must bounce: ground 0, table 0.76
  double net_height = 0;      // top of the net, world z
  double net_half_span = 0;   // |y| reach of the net
  double net_half_thickness = 0.01;
  double table_thickness = 0.03;
  double player_x = 0;   // players stand at x = -/+ player_x
  double partner_y = 0;  // in doubles, partners at y = -/+ partner_y
  // In doubles, the partner on the left (as it faces the net) stands this much nearer the net and
  // the one on the right this much further back: side by side, their arms (the rest pose's, held
  // out level) would overlap.
  double partner_stagger = 0;
  // ...so a partner stands this much nearer the net than player_x (negative: further back).
  double partner_forward(bool left) const { return left ? partner_stagger : -partner_stagger; }

  // Ball return: launched from x = launch_x on the far side (y in +-launch_y, z launch_z) with
  // horizontal speed in [launch_speed_lo, hi] to a landing point uniform on the player's half.
  double launch_x = 0, launch_y = 0, launch_z = 0;
  double launch_speed_lo = 0, launch_speed_hi = 0;
  // 1v1 and 2v2: each point's first ball from (0, 0, feed_z), horizontal speed in
  // [feed_speed_lo, hi], to a landing point uniform on the server's half.
  double feed_z = 0, feed_speed_lo = 0, feed_speed_hi = 0;

  // `start: "serve"`: each point's ball is tossed for the server from toss_forward m ahead of its
  // root and toss_side m to its racket (right) side, at height toss_z, rising at toss_speed m/s
  // (each drawn by the seed within toss_jitter m and toss_speed_jitter m/s of that); not struck
  // within serve_limit_s it is a fault. Tennis' service boxes reach service_line m
  // from the net (ITF rule 1); the singles server stands serve_y m off the centre mark.
  double toss_forward = 0, toss_side = 0, toss_z = 0, toss_speed = 0, serve_limit_s = 3;
  double toss_jitter = 0.03, toss_speed_jitter = 0.1;
  double service_line = 0, serve_y = 0;
  // On the ad court (left of the centre mark) the server stands turned ad_serve_turn radians to
  // its right (side-on, its left shoulder toward the net); the toss is placed from that stance.
  double ad_serve_turn = 0;

  // Reward target on the opponent's half, from the hitter's view: |x| in [target_x_lo, hi],
  // |y| <= target_y.
  double target_x_lo = 0, target_x_hi = 0, target_y = 0;
  bool reward_counts_hits = false;  // table tennis: r_ball adds the episode's successful returns

  // Static boxes the ball bounces off: the net, and the table top.
  std::vector<equipment::ArenaBox> arena() const;
  double half_width(bool doubles) const {
    return doubles ? half_width_doubles : half_width_singles;
  }
  // Is (x, y) inside `team`'s half, lines included?
  bool in_half(int team, double x, double y, bool doubles) const;
  static int side_sign(int team) { return team == 0 ? -1 : 1; }
};

RacketGame tennis_game(double net_height);
RacketGame table_tennis_game();

}  // namespace olympics::sports::racket
