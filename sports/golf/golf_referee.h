// The referees of one athlete's hole, as logic apart from physics: they read what each tick
// showed (GolfTick) and say what happened.
//
// Official (the Rules of Golf): a stroke is a club-ball contact the athlete makes; contacts
// within kOneStrokeS of the last belong to the same stroke (Rule 10.1a: a ball struck more than
// once in a stroke counts one). The hole is over when the ball is holed (at rest in the hole,
// all of it below the surface), or at the maximum score (Rule 21.2: `max_strokes`, or the time
// runs out: the ball is picked up and scores the maximum). A ball out of bounds costs a penalty
// stroke and is played again from where it was struck (Rule 18.2). The score is strokes plus
// penalties, at most the maximum.
// Paper (SMPLOlympics' golf task): one shot. "Contact" is its test (the club head within 0.2 m of
// the ball and the ball moved more than 0.01 m in x); the episode ends (from its third tick) on a
// fall, the ball within 0.15 m of a body other than the right hand, the ball not getting closer
// to the target after contact, the ball stopping after contact (|v| < 0.1 m/s: measured, a
// success within 1 m of the target), no contact after 60 ticks, or the ball moving back (x <
// -0.05) before contact.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "golf/golf_rules.h"

namespace olympics::sports::golf {

inline constexpr double kOneStrokeS = 0.3;    // s: club contacts closer than this are one stroke
inline constexpr double kAtRestSpeed = 0.01;  // m/s
inline constexpr double kAtRestS = 0.3;       // s below kAtRestSpeed: at rest
inline constexpr double kSeedStopSpeed = 0.1;
inline constexpr double kSeedSuccessM = 1.0;

// What one tick showed (positions in the lane's frame: the ball started at the origin).
struct GolfTick {
  int tick = 0;  // since the hole (paper: episode) began
  double t = 0;  // s since the hole began
  Eigen::Vector3d ball = Eigen::Vector3d::Zero(), ball_prev = Eigen::Vector3d::Zero();
  double ball_speed = 0;
  bool club_touch = false;  // the club touched the ball in this tick
  double club_touch_t = 0;  // when (the tick's first such contact)
  bool holed = false;
  bool out_of_bounds = false;
  Eigen::Vector3d target = Eigen::Vector3d::Zero();  // the hole or the seed's target, z = 0
  // Paper only.
  bool seed_contact = false;  // the seed's contact test held this tick
  bool body_near_ball = false;
  bool down = false;
};

// What the official referee asks of the match after a tick.
enum class GolfCall { None, Stroke, AtRest, OutOfBounds, Holed, PickedUp };

class HoleReferee {
 public:
  explicit HoleReferee(const GolfRules& rules) : rules_(rules) {}
  // The tick's call (one per tick: a stroke, the ball at rest, ...).
  GolfCall step(const GolfTick& s);
  int strokes() const { return strokes_; }
  int penalties() const { return penalties_; }
  bool over() const { return over_; }
  bool holed() const { return holed_; }
  int score() const;
  // A stroke was played and the ball has not come to rest since (the seed's C_b, per stroke).
  bool struck() const { return in_motion_; }
  std::string picked_up_reason() const { return picked_up_reason_; }

 private:
  GolfRules rules_;
  int strokes_ = 0, penalties_ = 0;
  bool in_motion_ = false;
  bool over_ = false, holed_ = false;
  double last_touch_ = -1e9;
  double slow_since_ = -1;
  std::string picked_up_reason_;
};

// How a paper episode ended.
struct SeedEnding {
  std::string reason;  // ball_stopped, fell, ball_near_body, ball_not_closer, no_contact, time
  bool hit = false;    // the seed's contact happened
  bool stopped = false;
  double stop_distance = 0;  // m from the target where the ball stopped
  bool success() const { return stopped && stop_distance < kSeedSuccessM; }
};

class SeedReferee {
 public:
  std::optional<SeedEnding> step(const GolfTick& s);
  bool contact() const { return contact_; }
  bool over() const { return ending_.has_value(); }
  const std::optional<SeedEnding>& ending() const { return ending_; }

 private:
  std::optional<SeedEnding> end(const std::string& why, double stop_distance = -1);
  bool contact_ = false;
  std::optional<SeedEnding> ending_;
};

}  // namespace olympics::sports::golf
