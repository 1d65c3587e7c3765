// The hurdles referee for one athlete's race, as logic apart from physics: it reads what each
// physics step showed (RaceStep) and decides the race once: finished (with its time), did not
// finish, or disqualified.
//
// Official (World Athletics): the finish is the moment any part of the torso reaches the finish
// line's plane (TR 19.2), timed to the physics step, interpolated, and read to 1/1000 s rounded up
// (TR 19.24); a foot on the ground outside the lane's lines (TR 17.3.1, 22.6.1) and a trail leg
// that passes a hurdle beside it, below the top (TR 22.6.2), disqualify; knocking hurdles over does
// not; a fall does not either, but an athlete down get_up_s in a row did not finish (ours: a race
// does not wait). Paper (the seed, SMPLOlympics' code): a finish is the root past the line; the
// run ends on a fall, a non-foot body pushing a hurdle with over 50 N, or the root more than
// 0.8 m off the lane's centre.
#pragma once

#include <optional>
#include <string>

#include "hurdles/hurdles_rules.h"

namespace olympics::sports::hurdles {

// What one physics step showed of the athlete (x along the track, y from the lane's centre).
struct RaceStep {
  double t = 0, dt = 0;  // s since the start at the step's end; the step's length
  double torso_front_x = -1e9, torso_front_x_prev = -1e9;  // the torso's foremost point
  double root_x = 0, root_x_prev = 0, root_y = 0;
  bool outside_lane = false;      // a foot touched the ground outside the lane's lines
  bool trail_leg_beside = false;  // a leg passed a standing hurdle's plane beside it, below its top
  bool hurdle_touch = false;      // a non-foot body pushed a hurdle with more than touch_force_n
  bool down = false;              // the fall detector's
};

struct RaceResult {
  enum class Kind { Finished, DidNotFinish, Disqualified };
  Kind kind = Kind::DidNotFinish;
  double time = 0;     // s, a finish's
  std::string reason;  // why not: left_lane, trail_leg, fell, touched_hurdle, left_track, time
  bool finished() const { return kind == Kind::Finished; }
  static RaceResult finish(double time) { return {Kind::Finished, time, ""}; }
  static RaceResult dnf(std::string why) { return {Kind::DidNotFinish, 0, std::move(why)}; }
  static RaceResult dq(std::string why) { return {Kind::Disqualified, 0, std::move(why)}; }
};

class RaceReferee {
 public:
  explicit RaceReferee(const HurdlesRules& rules) : rules_(rules) {}
  // Looks at one step; returns the race's result on the step that decides it, once.
  std::optional<RaceResult> step(const RaceStep& s);
  bool decided() const { return decided_; }

 private:
  std::optional<RaceResult> official_step(const RaceStep& s);
  std::optional<RaceResult> paper_step(const RaceStep& s);
  std::optional<RaceResult> decide(RaceResult r);

  HurdlesRules rules_;
  bool decided_ = false;
  double down_since_ = -1;  // official: when the athlete went down (-1: up)
};

// The finish time as a photo finish reads it: to 1/1000 s, rounded up (TR 19.24).
double photo_finish_time(double t);

}  // namespace olympics::sports::hurdles
