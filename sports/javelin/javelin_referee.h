// The javelin referee for one athlete's attempt, as logic apart from physics: it reads what each
// physics step showed (ThrowStep) and decides the attempt once (a mark or a foul).
//
// Official (TR 32.17, 32.20, 39): a foul is the javelin's first touch of the ground not by the
// tip of its metal head (a flat landing: the shaft touches in the same physics step or first),
// the tip landing outside the sector (or inside the arc), the athlete touching the arc or the
// ground beyond it, or a runway line or the ground outside the lines, before the javelin has
// landed, a fall before the release, or the time per attempt passing; the mark is from where
// the tip first touched to the arc's inner edge along the line to the arc's centre, rounded down
// to the centimetre.
// Paper (the seed, SMPLOlympics' code): by stage (control ticks since the attempt began: hold
// before hold_ticks, throw before throw_ticks, then flight), the episode ends when in the hold
// stage the javelin leaves the hand or, held, its attitude strays from the default; in the
// flight stage, the javelin is still near the hand; the mark is the javelin's x (from the start
// mark) where its centre drops below landing_z, with no tip, sector or arc check.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "athletics/attempt_series.h"
#include "javelin/javelin_rules.h"
#include "javelin/throwing_area.h"

namespace olympics::sports::javelin {

enum class Stage { Hold = 0, Throw = 1, Flight = 2 };
Stage stage_at(const JavelinRules& rules, int tick);

// What one physics step showed (world coordinates).
struct ThrowStep {
  double t = 0;                 // s since the attempt began
  int tick = 0;                 // control ticks since the attempt began (the tick in progress)
  bool held = false;            // the javelin is in the grip
  bool javelin_ground = false;  // the javelin touched the ground in this step
  bool head_only = false;       // ... with its head only
  Eigen::Vector3d tip_touch = Eigen::Vector3d::Zero();  // the head's contact point
  Eigen::Vector3d javelin_centre = Eigen::Vector3d::Zero();
  double hand_distance = 0;             // m from the right palm to the cord
  double attitude_error = 0;            // rad from the seed's default attitude
  bool athlete_beyond_arc = false;      // touched the arc or the ground beyond it
  bool athlete_outside_runway = false;  // touched a runway line or the ground outside them
  bool down = false;                    // the fall detector's
};

class JavelinReferee {
 public:
  // `start_x`: the athlete's start mark (paper measures from it).
  JavelinReferee(const JavelinRules& rules, const ThrowingArea& area, double start_x)
      : rules_(rules), area_(area), start_x_(start_x) {}
  // Looks at one step; returns the attempt's result on the step that decides it, once.
  std::optional<athletics::AttemptResult> step(const ThrowStep& s);
  bool decided() const { return decided_; }
  bool released() const { return released_; }

 private:
  std::optional<athletics::AttemptResult> official_step(const ThrowStep& s);
  std::optional<athletics::AttemptResult> paper_step(const ThrowStep& s);
  std::optional<athletics::AttemptResult> decide(athletics::AttemptResult r);

  JavelinRules rules_;
  ThrowingArea area_;
  double start_x_;
  bool decided_ = false;
  bool released_ = false;
};

}  // namespace olympics::sports::javelin
