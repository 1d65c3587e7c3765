#include "athletics/height_rounds.h"

#include <algorithm>
#include <stdexcept>

namespace olympics::sports::athletics {

HeightRounds::HeightRounds(int athletes, const std::vector<double>& heights, int tries_per_height,
                           double jump_off_step)
    : series_(athletes, HeightSeries(heights, tries_per_height)),
      due_(athletes, true),
      common_height_(heights.front()),
      lowest_(heights.front()),
      jump_off_step_(jump_off_step),
      contending_(athletes, false),
      cleared_now_(athletes, false),
      left_in_round_(athletes, -1) {
  if (athletes < 1) throw std::invalid_argument("HeightRounds: give at least one athlete");
}

void HeightRounds::record(int athlete, bool cleared) {
  if (over_ || !due_.at(athlete)) return;
  due_[athlete] = false;
  if (jump_off_)
    cleared_now_[athlete] = cleared;
  else
    series_[athlete].record(cleared);
  if (std::find(due_.begin(), due_.end(), true) != due_.end()) return;
  if (jump_off_)
    end_jump_off_round();
  else
    next_try_round();
}

void HeightRounds::next_try_round() {
  bool any = false;
  for (size_t i = 0; i < series_.size(); ++i) any |= due_[i] = series_[i].jumping();
  if (any) return;  // the next try at this height for those who failed
  for (size_t i = 0; i < series_.size(); ++i)
    if (series_[i].waiting()) {  // the round is over: the bar up for those who cleared
      series_[i].raise();
      due_[i] = true;
      common_height_ = series_[i].bar_height();
      any = true;
    }
  if (any) return;
  const std::vector<int> place = athletics::places(series_);
  if (jump_off_step_ > 0 && std::count(place.begin(), place.end(), 1) > 1 &&
      series_[std::find(place.begin(), place.end(), 1) - place.begin()].best() > 0)
    start_jump_off(place);
  else
    over_ = true;
}

void HeightRounds::start_jump_off(const std::vector<int>& place) {
  jump_off_ = true;
  for (size_t i = 0; i < series_.size(); ++i) {
    contending_[i] = due_[i] = place[i] == 1;
    if (contending_[i]) jump_off_height_ = series_[i].best() + jump_off_step_;
  }
}

void HeightRounds::end_jump_off_round() {
  int cleared = 0;
  for (size_t i = 0; i < series_.size(); ++i) cleared += contending_[i] && cleared_now_[i];
  if (cleared == 0) {
    // all failed: everyone again, the bar lowered, never below the competition's first height
    // (athletes who fail every try would otherwise take it under the supports' reach)
    jump_off_height_ = std::max(lowest_, jump_off_height_ - jump_off_step_);
  } else {
    for (size_t i = 0; i < series_.size(); ++i)
      if (contending_[i] && !cleared_now_[i]) {
        contending_[i] = false;
        left_in_round_[i] = jump_off_round_;
      }
    if (cleared == 1) {
      over_ = true;
      return;
    }
    jump_off_height_ += jump_off_step_;  // more than one cleared: the bar raised
  }
  ++jump_off_round_;
  for (size_t i = 0; i < series_.size(); ++i) {
    due_[i] = contending_[i];
    cleared_now_[i] = false;
  }
}

std::vector<int> HeightRounds::places() const {
  std::vector<int> place = athletics::places(series_);
  if (!over_ || !jump_off_) return place;
  // Among the tied first: the winner first, then those who left the jump-off later first.
  auto stayed_longer = [&](size_t a, size_t b) {
    const int la = left_in_round_[a] < 0 ? jump_off_round_ + 1 : left_in_round_[a];
    const int lb = left_in_round_[b] < 0 ? jump_off_round_ + 1 : left_in_round_[b];
    return la > lb;
  };
  std::vector<int> split = place;
  for (size_t i = 0; i < series_.size(); ++i) {
    if (place[i] != 1) continue;
    for (size_t j = 0; j < series_.size(); ++j)
      if (place[j] == 1 && stayed_longer(j, i)) ++split[i];
  }
  return split;
}

}  // namespace olympics::sports::athletics
