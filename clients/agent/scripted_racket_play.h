// How the scripted racket player plays each sport: the settings ScriptedRacketPolicy
// (scripted_racket.cpp) reads, one set per sport, each chosen on ball-return or match tuning seeds
// with its figures beside it (docs/racket-sports.md).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "step_controller.h"

namespace olympics::client::racket_play {

// How a sport is played: where the racket arm meets the ball best, where strokes go, how they
// are shaped. Table tennis meets the ball close and gently, tennis further out and harder.
// Chosen on ball-return tuning seeds 1-200 (docs/racket-sports.md); never on the benchmark's.
struct Play {
  Eigen::Vector3d sweet_spot;  // face centre at contact, heading frame from the root
  // Where the face meets a rally's ball (the planner's choice of contact and where the legs put
  // the body) when not the sweet spot: at the table, nearer the body's line (the sweet spot keeps
  // the ready point and the serve).
  std::optional<Eigen::Vector3d> meet_spot;
  double below = 0.5, above = 0.45;  // heights about the sweet spot the arm meets balls at, m
  double home_x = 0;                 // court x the player returns to between balls
  Eigen::Vector2d aim;               // where strokes should land (court frame, far half)
  // Where doubles strokes land, if not at aim (table tennis: 1v1 and ball return aim shorter,
  // doubles was not measured with it).
  std::optional<Eigen::Vector2d> doubles_aim;
  double net_margin = 0;        // m above the net
  double reach_fraction = 0.9;  // of the arm's full reach
  // How much further the trunk's lean and turn take the shoulder; 0: the arm alone reaches (a
  // heavy racket swung from a leaning trunk topples the player).
  double trunk_reach = 0;
  double table_clearance = 0.12;  // a ball met over the table is at least this far above it
  double max_back = 0;            // backswing, m along the swing's line
  double swing_s = 0.25;          // the swing from the backswing to the ball
  double follow = 0;              // follow-through, m
  double max_speed = 0;           // face speed, m/s
  // The straight backswing is drawn over this long, ending as the swing starts; until then the
  // face waits at the ready point. 0: it is held at the back point from the stroke's planning.
  double draw_s = 0;
  // The arm is asked for where the face should be this long after the tick starts (measured:
  // asking for the tick's end, or later, meets fewer balls).
  double ask_ahead_s = 0.02;
  // Gravity compensation, in multiples of the weight (control/drive_target.h: 3 holds a still
  // arm; a swinging one met more balls with less).
  double gravity_scale = 2;
  double commit_s = 0.2;           // this close to the ball, the stroke is no longer re-planned
  double settle_s = 0.5;           // the legs stop walking this long before a reachable ball
  double doubles_step_back = 0.7;  // m further back than home while the partner plays
  // After its stroke the player stands this long (s) before it walks home.
  double home_after_s = 0.4;
  // Table-tennis doubles serve: the face and its swing turned this much further across (left,
  // radians) than planned. Swung across the body toward the diagonal, the arm sends the ball about
  // 11 degrees right of the planned line (tuning seeds 1-4: 25.5 degrees asked, 14.7 delivered).
  double doubles_serve_turn = 0;
  // Table-tennis doubles: the right-hand partner (facing the net; its mark 0.2 m further back)
  // waits at this y (court frame, + left) while its stroke is next; none: at its mark.
  std::optional<double> doubles_next_right_y;
  // The face is asked for this far off where the plan meets the ball (heading frame, m), for the
  // arm's steady miss; only for balls met between the racket shoulder's line and the root's
  // (face_aim_bias below).
  Eigen::Vector3d face_aim_bias = Eigen::Vector3d::Zero();
  // The arm meets every ball with the face's front side (the one whose normal is the hand's z):
  // a ball across the body is met with the arm reaching across, the wrist as on the forehand.
  // false: either side, as the inverse kinematics finds nearer (a two-sided face). 1v1 and
  // ball return only: doubles keeps either side (scripted_racket.cpp).
  bool front_face_only = false;
  double walk_speed = 0.6;       // m/s the legs cover, roughly, toward a ball out of reach
  double balance_ahead = -0.03;  // the centre of mass held this far ahead of the ankles
  double horizon_s = 0;          // how far ahead the ball is predicted
  // The legs walk to a ball out of reach only while they can still get there in time: its
  // stance no further than walk_speed × the time left plus this (the arm meets balls that far
  // short of the stance); beyond, they stand. 0: they always walk.
  double chase_slack = 0;
  // A ball swung at and missed (its committed contact passed while it still comes) is let go:
  // the legs stand until the ball is dead or struck, rather than chase it along its path behind
  // the player. false: the planner picks a later point on the path and the legs walk there.
  bool let_go_missed = false;
  // A new point drops the stroke left from the point before. Kept, a stroke committed when the
  // last point ended runs out against the new ball and marks it missed (let_go_missed): the fed
  // player then plans nothing for the feed. false: kept (tennis, where let_go_missed is off and
  // no feed went unplanned: 0 of 120 on tuning seeds 1-4).
  bool forget_stroke_at_new_point = false;
  // A new point of a match starts the legs afresh (standing, or a step begun from the feet as
  // they are): the match puts every player back at its mark, standing still, where a step under
  // way when the last point ended would otherwise run on from where the feet were before. Not in
  // ball return, whose player is not put back between balls.
  struct FreshLegs {
    bool at_new_point = false;
    // ...and they step at once toward where they are sent, however near (beyond where a walk
    // stops), the first step by the trailing foot
    // (StepController::step_at_once_trailing_foot_first). false: they stand until sent beyond the
    // walker's start distance (0.3 m) or off balance.
    bool step_at_once = false;
    // ...in doubles too; false: in doubles the legs run on across points (table tennis, whose
    // fresh legs were measured in 1v1 only).
    bool in_doubles = true;
    // ...and at a point begun by a toss (`start: "serve"`: the ball hardly moving across) too;
    // false: only at fed points, and at a toss the legs run on from the point before.
    bool at_tosses = true;

    // Whether a new point, where the match put the players back, starts the legs afresh.
    bool applies_to(bool doubles, bool tossed) const {
      return at_new_point && (in_doubles || !doubles) && (at_tosses || !tossed);
    }
  };
  FreshLegs fresh_legs;
  // The swing as an arc about the vertical through the shoulder (the arm turning as one, the
  // face at a constant distance), at the least of `arc_speeds` that returns the ball in.
  double max_back_angle = 0;  // radians of backswing along the arc; 0: a straight swing
  double follow_angle = 0.5;  // radians of follow-through
  // ...and while the legs still walk to the ball (a racket held far back topples the walker).
  double walking_back_angle = 0.4;
  // While the legs still walk to a ball within reach, the arm readies the arc as seen from where
  // they are taking the body, drawn back no further than `walking_back_angle`; the joint-space
  // swing starts once they stop. false: the joint-space swing from the first tick the ball is
  // within reach, its posture solved where the body stands (so it sweeps across as the body walks).
  bool swing_once_settled = false;
  std::vector<double> arc_speeds;
  double arc_drive = 1;  // the arc is driven this much faster than planned (the arm lags)
  // Once the ball is within reach, the arc is swung in joint space (scripted_tennis_swing.h):
  // the arm held in the posture that meets the ball, turned about the shoulder's vertical from
  // rest at the backswing, asked `swing_lead_s` ahead of the face's planned timing.
  bool joint_swing = false;
  double swing_lead_s = 0;
  // The serve swung on the arc in joint space (control::plan_arc_serve) at the least of these
  // face speeds (m/s) that lands in the box; empty: the straight swing toward the box. Its
  // face normal is planned, then tilted down (about the horizontal across it) and turned right
  // by these (radians), for the arm's error at that speed; the free arm swings the other way.
  std::vector<double> serve_speeds;
  double serve_tilt_down = 0, serve_turn_right = 0;
  // The serve meets the toss within this share of the arm's full reach; unset: the rally's
  // `reach_fraction`.
  std::optional<double> serve_reach_fraction;
  StepGains legs;
};

Play table_play();
Play tennis_play();

// The face's aim bias (Play::face_aim_bias) for a ball met at `met` beside a racket shoulder at
// `shoulder` (heading frame, from the root): only between the shoulder's line and the root's.
Eigen::Vector3d face_aim_bias(const Play& play, const Eigen::Vector3d& met,
                              const Eigen::Vector3d& shoulder);

}  // namespace olympics::client::racket_play
