// A vertical event's competition (World Athletics TR 26) among N athletes who jump at the same
// time, each at its own installation: the bar is one height for all; at it, every athlete still
// in makes its first try, then those who failed their second, then their third (a try round each,
// so the start order is kept); three failures in a row eliminate. The bar goes up to the next
// height only when every athlete still in has cleared it or is out. Ties for first place after
// the countback (TR 26.8) go to a jump-off (TR 26.9): one try each at the next height, the bar
// raised by the step while more than one clears and lowered by it when all fail (not below the
// first height), until one alone clears. Passing a height is not modelled: every athlete jumps at
// every height.
#pragma once

#include <vector>

#include "athletics/attempt_series.h"

namespace olympics::sports::athletics {

class HeightRounds {
 public:
  // `jump_off_step` m: the jump-off's raise and lowering; 0 leaves a tie for first shared.
  HeightRounds(int athletes, const std::vector<double>& heights, int tries_per_height,
               double jump_off_step);

  // Whether `athlete` makes an attempt in the current try round and has not yet made it.
  bool due(int athlete) const { return due_.at(athlete); }
  double bar_height() const { return jump_off_ ? jump_off_height_ : common_height_; }
  // `athlete`'s attempt at bar_height() (ignored unless due); ends the try round once every
  // athlete due has jumped, then starts the next one, raises the bar or starts the jump-off.
  void record(int athlete, bool cleared);
  bool over() const { return over_; }
  bool in_jump_off() const { return jump_off_; }
  const HeightSeries& series(int athlete) const { return series_.at(athlete); }
  const std::vector<HeightSeries>& all_series() const { return series_; }
  // Places (1 = first): the countback's, with first place split by the jump-off once decided.
  std::vector<int> places() const;

 private:
  void next_try_round();
  void start_jump_off(const std::vector<int>& places);
  void end_jump_off_round();

  std::vector<HeightSeries> series_;
  std::vector<bool> due_;
  double common_height_;
  double lowest_;  // the jump-off's bar comes no lower than the first height
  double jump_off_step_;
  bool over_ = false;
  // The jump-off: who is still in it, its cleared tries this round, and when each one left it.
  bool jump_off_ = false;
  double jump_off_height_ = 0;
  int jump_off_round_ = 0;
  std::vector<bool> contending_, cleared_now_;
  std::vector<int> left_in_round_;  // -1: never in the jump-off, or still in it
};

}  // namespace olympics::sports::athletics
