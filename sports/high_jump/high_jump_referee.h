// The high-jump referee for one attempt, as logic apart from physics: it reads what each physics
// step showed (BarStep) and decides the attempt once (cleared or failed, with why).
//
// Official (TR 27.2): a failure is the bar dislodged (it left its supports), touching the ground
// or the landing area beyond the bar's plane before going over it (the root crossing the plane
// above the bar, between the uprights), or the time per attempt passing (and, for a simulation,
// a fall before the jump, and leaving the fan-shaped run-up before going over); a clearance is
// going over and resting on the landing area settle_s with the bar still up. Paper (the seed):
// ends on a fall, the bar displaced or leaving the run-up area (our rectangle: the seed gives no
// bounds); a clearance is every body past the plane by 0.1 m with the bar up, the root having
// crossed the plane above the bar (passing under it is `under_the_bar`).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "high_jump/high_jump_rules.h"

namespace olympics::sports::high_jump {

// One physics step; positions relative to the bar's centre on the ground (x across the plane,
// y along the bar).
struct BarStep {
  double t = 0;  // s since the attempt began
  double bar_height = 1.0;
  bool bar_in_place = true;
  Eigen::Vector3d root = Eigen::Vector3d::Zero(), root_prev = Eigen::Vector3d::Zero();
  double min_body_x = -1e9;     // the body origin nearest the run-up
  bool touched_beyond = false;  // the ground or the mat touched beyond the plane
  bool down = false;
};

struct BarDecision {
  bool cleared = false;
  std::string reason;  // a failure's: bar_dislodged, touched_beyond, fell, left_area, time,
                       // under_the_bar (paper)
};

class HighJumpReferee {
 public:
  explicit HighJumpReferee(const HighJumpRules& rules) : rules_(rules) {}
  std::optional<BarDecision> step(const BarStep& s);
  bool decided() const { return decided_; }
  // Official: is a root (relative to the bar's centre on the ground) inside the run-up fan, or
  // past the bar's plane (where the landing area's own rule applies)?
  bool in_runup(const Eigen::Vector3d& root) const;
  bool over() const { return over_; }  // the root went over the bar

 private:
  std::optional<BarDecision> official_step(const BarStep& s);
  std::optional<BarDecision> paper_step(const BarStep& s);
  // The root crossed the bar's plane this step above the bar (and between the uprights).
  bool crossed_above(const BarStep& s, bool between_uprights) const;
  std::optional<BarDecision> decide(bool cleared, std::string why);

  HighJumpRules rules_;
  bool decided_ = false;
  bool over_ = false;
  std::optional<double> landed_at_;
};

}  // namespace olympics::sports::high_jump
