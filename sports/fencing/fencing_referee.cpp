#include "fencing/fencing_referee.h"

namespace olympics::sports::fencing {

FencingReferee::FencingReferee(const FencingRules& rules) : rules_(rules), idle_(rules.idle_s) {}

void FencingReferee::touch(int fencer, double time) {
  if (halt_ || bout_over()) return;
  if (first_toucher_ < 0) {
    first_toucher_ = fencer;
    first_touch_time_ = time;
  } else if (fencer != first_toucher_ && time - first_touch_time_ <= rules_.double_window_s) {
    second_touched_ = true;
  }  // else: the same fencer again, or locked out
}

void FencingReferee::update(double time) {
  if (halt_ || bout_over()) return;
  if (first_toucher_ >= 0) {
    if (time - first_touch_time_ <= rules_.double_window_s) return;  // the window is open
    Halt h;
    h.time = first_touch_time_;
    if (!second_touched_) {
      h.reason = "touch";
      h.scored[first_toucher_] = true;
    } else if (score_[0] == rules_.touches - 1 && score_[1] == rules_.touches - 1) {
      h.reason = "double_annulled";
    } else {
      h.reason = "double";
      h.scored = {true, true};
    }
    return decide(h);
  }
  if (idle_.expired(time)) decide({"idle", {}, -1, time});
}

void FencingReferee::off_piste(const std::array<bool, 2>& off, double time) {
  if (halt_ || bout_over() || first_toucher_ >= 0 || !(off[0] || off[1])) return;
  decide({"off_piste", {}, off[0] && off[1] ? -1 : (off[0] ? 0 : 1), time});
}

void FencingReferee::falls(const std::array<bool, 2>& down, double time) {
  if (halt_ || bout_over() || first_toucher_ >= 0 || !(down[0] || down[1])) return;
  Halt h{"fall", {}, down[0] && down[1] ? -1 : (down[0] ? 0 : 1), time};
  if (rules_.fall_penalty == FallPenalty::Touch && h.culprit >= 0) h.scored[1 - h.culprit] = true;
  decide(h);
}

void FencingReferee::decide(Halt h) {
  for (int f = 0; f < 2; ++f)
    if (h.scored[f]) ++score_[f];
  for (int f = 0; f < 2; ++f)
    if (score_[f] >= rules_.touches && score_[1 - f] < rules_.touches) winner_ = f;
  halt_ = std::move(h);
}

void FencingReferee::next_exchange(double time) {
  halt_.reset();
  first_toucher_ = -1;
  second_touched_ = false;
  idle_.restart(time);
}

}  // namespace olympics::sports::fencing
