#include "long_jump/long_jump_referee.h"

#include <algorithm>
#include <cmath>

namespace olympics::sports::long_jump {

using athletics::AttemptResult;

std::optional<AttemptResult> LongJumpReferee::decide(AttemptResult r) {
  decided_ = true;
  return r;
}

std::optional<AttemptResult> LongJumpReferee::step(const JumpStep& s) {
  if (decided_) return std::nullopt;
  past_line_ = past_line_ || s.feet_front_x > rules_.line_x;
  return rules_.official ? official_step(s) : paper_step(s);
}

std::optional<AttemptResult> LongJumpReferee::official_step(const JumpStep& s) {
  const double line = rules_.line_x;
  if (!landed_) {
    // TR 30.1.1 as the issue words it: any part past the line while still on the ground; and
    // TR 30.1.4: touching the ground between the line and the pit.
    if (s.on_ground && (s.front_x > line || s.ground_front_x > line))
      return decide(AttemptResult::foul("past_the_line"));
    // Airborne past the line the athlete has taken off: the fall detector's low, tilted body is
    // a dive into the pit, not a fall (TR 30 knows no fall foul; the landing decides).
    const bool flying_past_line = !s.on_ground && s.front_x > line;
    if (s.in_pit) {
      landed_ = true;
      landed_at_ = s.t;
    } else if (s.down && !flying_past_line) {
      return decide(AttemptResult::foul("fell"));
    } else if (s.t > rules_.attempt_s) {
      return decide(AttemptResult::foul("time"));
    }
  }
  if (!landed_) return std::nullopt;
  // TR 30.1.5: landing, touching the ground outside the pit nearer the line than the nearest
  // break in the sand.
  if (s.on_ground && s.ground_front_x > line && s.ground_front_x < nearest_break_x_)
    return decide(AttemptResult::foul("outside_the_pit"));
  if (s.in_pit) nearest_break_x_ = std::min(nearest_break_x_, s.pit_near_x);
  mark_ = nearest_break_x_ - line;  // perpendicular to the line, which runs along y
  if (s.t - landed_at_ >= rules_.settle_s) return decide(AttemptResult::measured(mark_));
  return std::nullopt;
}

std::optional<AttemptResult> LongJumpReferee::paper_step(const JumpStep& s) {
  if (past_line_ && (s.on_ground || s.in_pit)) {  // the first contact after the line: landing
    landed_ = true;
    mark_ = s.mean_body.x() - rules_.line_x;
    return decide(AttemptResult::measured(mark_));
  }
  if (s.down) return decide(AttemptResult::foul("fell"));
  if (std::abs(s.root_y) > 0.5 * rules_.runway_width)
    return decide(AttemptResult::foul("left_runway"));
  if (s.t > rules_.attempt_s) return decide(AttemptResult::foul("time"));
  return std::nullopt;
}

}  // namespace olympics::sports::long_jump
