#include "javelin/javelin_referee.h"

#include <cmath>

namespace olympics::sports::javelin {

using athletics::AttemptResult;

Stage stage_at(const JavelinRules& rules, int tick) {
  if (tick < rules.hold_ticks) return Stage::Hold;
  return tick < rules.throw_ticks ? Stage::Throw : Stage::Flight;
}

std::optional<AttemptResult> JavelinReferee::decide(AttemptResult r) {
  decided_ = true;
  return r;
}

std::optional<AttemptResult> JavelinReferee::step(const ThrowStep& s) {
  if (decided_) return std::nullopt;
  released_ = released_ || !s.held;
  return rules_.official ? official_step(s) : paper_step(s);
}

std::optional<AttemptResult> JavelinReferee::official_step(const ThrowStep& s) {
  // TR 32.17 (b): touching the arc or the ground beyond it, or the lines or the ground outside
  // the runway, counts until the implement has landed; the landing's own step counts too.
  if (s.athlete_beyond_arc) return decide(AttemptResult::foul("arc"));
  if (s.athlete_outside_runway) return decide(AttemptResult::foul("runway"));
  if (released_ && s.javelin_ground) {
    // TR 39.1: the tip of the metal head strikes the ground before any other part.
    if (!s.head_only) return decide(AttemptResult::foul("flat"));
    // TR 32.18 (TR 39.1 (d)): inside the inner edges of the sector lines.
    if (!area_.in_sector(s.tip_touch)) return decide(AttemptResult::foul("sector"));
    return decide(AttemptResult::measured(area_.mark(s.tip_touch)));
  }
  if (!released_ && s.down) return decide(AttemptResult::foul("fell"));
  if (s.t > rules_.attempt_s) return decide(AttemptResult::foul("time"));
  return std::nullopt;
}

std::optional<AttemptResult> JavelinReferee::paper_step(const ThrowStep& s) {
  const double stray = rules_.stray_deg * M_PI / 180.0;
  switch (stage_at(rules_, s.tick)) {
    case Stage::Hold:
      if (released_) return decide(AttemptResult::foul("dropped"));
      if (s.attitude_error > stray) return decide(AttemptResult::foul("strayed"));
      break;
    case Stage::Throw:
      if (s.held && s.attitude_error > stray) return decide(AttemptResult::foul("strayed"));
      break;
    case Stage::Flight:
      if (s.hand_distance < rules_.hand_near) return decide(AttemptResult::foul("not_thrown"));
      break;
  }
  if (released_ && s.javelin_centre.z() < rules_.landing_z)
    return decide(AttemptResult::measured(s.javelin_centre.x() - start_x_));
  if (s.t > rules_.attempt_s) return decide(AttemptResult::foul("time"));
  return std::nullopt;
}

}  // namespace olympics::sports::javelin
