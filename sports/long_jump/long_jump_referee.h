// The long-jump referee for one athlete's attempt, as logic apart from physics: it reads what
// each physics step showed (JumpStep) and decides the attempt once (a mark or a foul).
//
// Official (TR 30): a foul is any part of the body past the foul line while the athlete is still
// on the ground (taking off or running through), touching the ground between the line and the
// pit or outside the pit nearer the line than the mark, a fall before the jump, or the time per
// attempt passing; the mark is the nearest break in the sand to the foul line that any part of
// the body made, measured perpendicular to the line (x - line_x), taken once the landing settled.
// Paper (the seed, SMPLOlympics' code): "past the line" = a foot past x = line; the landing is
// the first contact after that; the mark is the mean x of all bodies then, minus line_x; a fall
// or leaving the 1 m runway ends the attempt without a mark.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "athletics/attempt_series.h"
#include "long_jump/long_jump_rules.h"

namespace olympics::sports::long_jump {

// What one physics step showed of the athlete (x along the runway, y from the lane's centre).
struct JumpStep {
  double t = 0;                  // s since the attempt began
  bool on_ground = false;        // touched the ground outside the pit
  double ground_front_x = -1e9;  // the foremost such contact point
  double front_x = -1e9;         // the foremost point of the body
  double feet_front_x = -1e9;    // the foremost foot body (paper)
  bool in_pit = false;           // touched the sand
  double pit_near_x = 1e9;       // the sand contact nearest the line
  Eigen::Vector3d mean_body = Eigen::Vector3d::Zero();
  double root_y = 0;  // from the lane's centre
  bool down = false;  // the fall detector's
};

class LongJumpReferee {
 public:
  explicit LongJumpReferee(const LongJumpRules& rules) : rules_(rules) {}
  // Looks at one step; returns the attempt's result on the step that decides it, once.
  std::optional<athletics::AttemptResult> step(const JumpStep& s);
  bool decided() const { return decided_; }
  // The seed's reward phase: a foot has passed the line.
  bool past_line() const { return past_line_; }
  // The seed's landing (paper) or the first break in the sand (official), and its mark so far.
  bool landed() const { return landed_; }
  double mark() const { return mark_; }

 private:
  std::optional<athletics::AttemptResult> official_step(const JumpStep& s);
  std::optional<athletics::AttemptResult> paper_step(const JumpStep& s);
  std::optional<athletics::AttemptResult> decide(athletics::AttemptResult r);

  LongJumpRules rules_;
  bool decided_ = false;
  bool past_line_ = false;
  bool landed_ = false;
  double landed_at_ = 0;
  double nearest_break_x_ = 1e9;
  double mark_ = 0;
};

}  // namespace olympics::sports::long_jump
