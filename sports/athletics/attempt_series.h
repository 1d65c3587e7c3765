// A field event's series of attempts and how athletes rank by them (World Athletics TR 25, 26):
// horizontal events (long jump, throws) keep each attempt's mark or foul and rank by the best,
// ties by the second best and so on; vertical events (high jump) raise the bar through a list of
// heights, three tries at each, and rank by the best height, ties by the countback (fewest
// failures at that height, then fewest in the whole competition).
#pragma once

#include <string>
#include <vector>

namespace olympics::sports::athletics {

// One attempt of a horizontal event: a valid mark (m) or a foul (`reason`).
struct AttemptResult {
  bool valid = false;
  double mark = 0;
  std::string reason;  // why it was a foul ("past_the_line", "time", "fell", ...)
  static AttemptResult measured(double mark) { return {true, mark, ""}; }
  static AttemptResult foul(std::string why) { return {false, 0, std::move(why)}; }
};

class HorizontalSeries {
 public:
  explicit HorizontalSeries(int attempts) : attempts_(attempts) {}
  void record(const AttemptResult& result) { results_.push_back(result); }
  bool done() const { return static_cast<int>(results_.size()) >= attempts_; }
  int attempts() const { return attempts_; }
  int taken() const { return static_cast<int>(results_.size()); }
  const std::vector<AttemptResult>& results() const { return results_; }
  // The valid marks, best first (empty: no valid mark).
  std::vector<double> marks_best_first() const;
  double best() const;  // 0 without a valid mark
  int fouls() const;

 private:
  int attempts_;
  std::vector<AttemptResult> results_;
};

// Whether `a` ranks before `b` (TR 25.22: best mark, then the next best, ...).
bool ranks_before(const HorizontalSeries& a, const HorizontalSeries& b);

// One athlete's series in a vertical event. The bar goes up per round (TR 26.1): a clearance
// leaves the athlete waiting at its height until every athlete still in has cleared it or is out;
// the competition (HeightRounds) then calls raise().
class HeightSeries {
 public:
  // `heights` rising; `tries_per_height` failures in a row end the series (TR 26.4: three).
  HeightSeries(std::vector<double> heights, int tries_per_height);
  double bar_height() const { return heights_.at(height_index_); }
  int tries_left_at_height() const { return tries_per_height_ - failures_here_; }
  // An attempt at bar_height(): a clearance waits for raise() (or ends the series after the last
  // height); a third failure in a row ends it.
  void record(bool cleared);
  // Still to jump at bar_height(): in the competition and not over this height yet.
  bool jumping() const { return !done_ && !cleared_here_; }
  // Cleared bar_height() and waits for the round to end and the bar to go up.
  bool waiting() const { return !done_ && cleared_here_; }
  void raise();  // to the next height; only while waiting()
  bool done() const { return done_; }
  double best() const { return best_; }  // 0: no height cleared
  int failures_at_best() const { return failures_at_best_; }
  int total_failures() const { return total_failures_; }
  int attempts() const { return attempts_; }

 private:
  std::vector<double> heights_;
  int tries_per_height_;
  size_t height_index_ = 0;
  int failures_here_ = 0;
  int failures_at_best_ = 0;
  int total_failures_ = 0;
  int attempts_ = 0;
  double best_ = 0;
  bool cleared_here_ = false;
  bool done_ = false;
};

// Whether `a` ranks before `b` (TR 26.8: best height, then fewest failures at it, then fewest
// failures in all).
bool ranks_before(const HeightSeries& a, const HeightSeries& b);

// Places (1 = first) of every athlete; athletes that neither ranks before the other share a
// place, and the next place is skipped (1, 1, 3).
template <typename Series>
std::vector<int> places(const std::vector<Series>& series) {
  std::vector<int> place(series.size(), 1);
  for (size_t i = 0; i < series.size(); ++i)
    for (size_t j = 0; j < series.size(); ++j)
      if (ranks_before(series[j], series[i])) ++place[i];
  return place;
}

}  // namespace olympics::sports::athletics
