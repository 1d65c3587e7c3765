#include "high_jump/high_jump_referee.h"

#include <cmath>

namespace olympics::sports::high_jump {

std::optional<BarDecision> HighJumpReferee::decide(bool cleared, std::string why) {
  decided_ = true;
  return BarDecision{cleared, std::move(why)};
}

std::optional<BarDecision> HighJumpReferee::step(const BarStep& s) {
  if (decided_) return std::nullopt;
  if (!s.bar_in_place) return decide(false, "bar_dislodged");
  return rules_.official ? official_step(s) : paper_step(s);
}

bool HighJumpReferee::crossed_above(const BarStep& s, bool between_uprights) const {
  const bool crossed = s.root_prev.x() < 0 && s.root.x() >= 0;
  return crossed && s.root.z() > s.bar_height &&
         (!between_uprights || std::abs(s.root.y()) < 0.5 * rules_.upright_gap);
}

std::optional<BarDecision> HighJumpReferee::official_step(const BarStep& s) {
  if (crossed_above(s, true)) over_ = true;
  if (s.touched_beyond && !over_) return decide(false, "touched_beyond");
  if (over_) {
    if (s.touched_beyond && !landed_at_) landed_at_ = s.t;
    if (landed_at_ && s.t - *landed_at_ >= rules_.settle_s) return decide(true, "");
    return std::nullopt;
  }
  if (!in_runup(s.root)) return decide(false, "left_area");
  if (s.down) return decide(false, "fell");
  if (s.t > rules_.attempt_s) return decide(false, "time");
  return std::nullopt;
}

bool HighJumpReferee::in_runup(const Eigen::Vector3d& root) const {
  return root.x() >= 0 || root.head<2>().norm() <= rules_.runup_radius;
}

std::optional<BarDecision> HighJumpReferee::paper_step(const BarStep& s) {
  // The seed's test (every body past the plane with the bar up) would also pass a walk under a
  // high bar (the seed's 2.0 m bar stands above a walking humanoid's head): the root must also
  // have crossed the plane above the bar, as the official referee asks (not between the
  // uprights: the seed's bar has none to check).
  if (crossed_above(s, false)) over_ = true;
  if (s.min_body_x > 0.1) return over_ ? decide(true, "") : decide(false, "under_the_bar");
  if (s.down) return decide(false, "fell");
  // The run-up area (the seed names one without its bounds): from 2 m behind the start mark
  // to 4 m past the bar, 2 m beyond the uprights on either side and behind the start.
  const double start_x = -rules_.bar_x, start_y = -rules_.bar_y;
  const double side = 0.5 * rules_.upright_gap + 2.0;
  if (s.root.x() < start_x - 2 || s.root.x() > 4 || s.root.y() < std::min(start_y - 2, -side) ||
      s.root.y() > std::max(start_y + 2, side))
    return decide(false, "left_area");
  if (s.t > rules_.attempt_s) return decide(false, "time");
  return std::nullopt;
}

}  // namespace olympics::sports::high_jump
