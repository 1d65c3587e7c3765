#include "hurdles/race_referee.h"

#include <algorithm>
#include <cmath>

namespace olympics::sports::hurdles {

double photo_finish_time(double t) { return std::ceil(t * 1000.0 - 1e-9) / 1000.0; }

std::optional<RaceResult> RaceReferee::decide(RaceResult r) {
  decided_ = true;
  return r;
}

std::optional<RaceResult> RaceReferee::step(const RaceStep& s) {
  if (decided_) return std::nullopt;
  return rules_.official ? official_step(s) : paper_step(s);
}

std::optional<RaceResult> RaceReferee::official_step(const RaceStep& s) {
  if (s.outside_lane) return decide(RaceResult::dq("left_lane"));
  if (s.trail_leg_beside) return decide(RaceResult::dq("trail_leg"));
  const double line = rules_.race_m;
  if (s.torso_front_x >= line) {
    // The moment the torso reached the line, between this step's start and end.
    const double moved = s.torso_front_x - s.torso_front_x_prev;
    const double share =
        moved > 0 ? std::clamp((line - s.torso_front_x_prev) / moved, 0.0, 1.0) : 1.0;
    return decide(RaceResult::finish(photo_finish_time(s.t - s.dt + share * s.dt)));
  }
  if (!s.down) {
    down_since_ = -1;
  } else {
    if (down_since_ < 0) down_since_ = s.t;
    if (s.t - down_since_ >= rules_.get_up_s) return decide(RaceResult::dnf("fell"));
  }
  return std::nullopt;
}

std::optional<RaceResult> RaceReferee::paper_step(const RaceStep& s) {
  if (s.root_x > rules_.race_m) return decide(RaceResult::finish(s.t));
  if (s.down) return decide(RaceResult::dnf("fell"));
  if (s.hurdle_touch) return decide(RaceResult::dnf("touched_hurdle"));
  if (std::abs(s.root_y) > rules_.track_half_width) return decide(RaceResult::dnf("left_track"));
  return std::nullopt;
}

}  // namespace olympics::sports::hurdles
