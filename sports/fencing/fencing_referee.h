// The referee of an épée bout (SPORTS.md, Fencing; FIE rules where the seed stops), as logic
// alone: it is told of touches (at physics-step times), fencers leaving the piste, falls and the
// passing time, and it decides each exchange. It keeps no physics, so it is tested with made-up
// sequences.
//
// - A touch starts the épée's lock-out window (`double_window_s`, 40-50 ms: shorter than a 30 Hz
//   tick, so touches are reported at the physics rate): the other fencer's touch inside it makes
//   a double touch, both score; touches after it are locked out. Once the window has closed the
//   exchange is decided. A double touch that would give both fencers the bout's last touch is
//   annulled (no score), as the FIE rules say of a tied last touch.
// - Leaving the piste halts play without a score (the seed: both fencers go back to their
//   lines), unless a touch was already made.
// - A fall halts play without a score (épée has no touch for a fall: the referee halts the bout);
//   the project's "touch" penalty, a setting, gives the opponent a touch instead (both at once:
//   no score).
// - No touch for `idle_s` (non-combativity) halts play without a score.
// - After every halt both fencers go back to their on-guard lines (the match does that) and
//   next_exchange() resumes play. The bout ends when a fencer reaches `touches`.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "framework/stall_timer.h"

namespace olympics::sports::fencing {

enum class FallPenalty { Touch, Halt };

struct FencingRules {
  int touches = 5;
  double double_window_s = 0.04;
  FallPenalty fall_penalty = FallPenalty::Halt;
  double idle_s = 60;
};

// How an exchange ended.
struct Halt {
  std::string reason;  // "touch", "double", "double_annulled", "off_piste", "fall", "idle"
  std::array<bool, 2> scored{};  // which fencers scored
  int culprit = -1;              // who left the piste or fell (-1: both, or none)
  double time = 0;               // when play stopped (s)
};

class FencingReferee {
 public:
  explicit FencingReferee(const FencingRules& rules);

  // Fencer (0 or 1) touched a valid target at `time` (seconds into the bout).
  void touch(int fencer, double time);
  // Checks at every physics step: decides a touch once its window has closed, and halts an
  // idle bout.
  void update(double time);
  // Per tick: who is off the piste, who is down.
  void off_piste(const std::array<bool, 2>& off, double time);
  void falls(const std::array<bool, 2>& down, double time);

  // The decided exchange, if any; the score already counts it.
  const std::optional<Halt>& halt() const { return halt_; }
  // The fencers are back on guard: play resumes.
  void next_exchange(double time);

  const std::array<int, 2>& score() const { return score_; }
  bool bout_over() const { return winner_ >= 0; }
  int winner() const { return winner_; }  // -1 until a fencer reaches the bout's touches
  // A touch was made and its window is still open.
  bool touch_pending() const { return first_toucher_ >= 0 && !halt_; }

 private:
  void decide(Halt h);

  FencingRules rules_;
  std::array<int, 2> score_{0, 0};
  int winner_ = -1;
  int first_toucher_ = -1;
  double first_touch_time_ = 0;
  bool second_touched_ = false;
  StallTimer idle_;
  std::optional<Halt> halt_;
};

}  // namespace olympics::sports::fencing
