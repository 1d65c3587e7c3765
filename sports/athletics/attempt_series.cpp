#include "athletics/attempt_series.h"

#include <algorithm>
#include <stdexcept>

namespace olympics::sports::athletics {

std::vector<double> HorizontalSeries::marks_best_first() const {
  std::vector<double> marks;
  for (const auto& r : results_)
    if (r.valid) marks.push_back(r.mark);
  std::sort(marks.begin(), marks.end(), std::greater<>());
  return marks;
}

double HorizontalSeries::best() const {
  const auto marks = marks_best_first();
  return marks.empty() ? 0.0 : marks.front();
}

int HorizontalSeries::fouls() const {
  return static_cast<int>(std::count_if(results_.begin(), results_.end(),
                                        [](const AttemptResult& r) { return !r.valid; }));
}

bool ranks_before(const HorizontalSeries& a, const HorizontalSeries& b) {
  const auto ma = a.marks_best_first(), mb = b.marks_best_first();
  for (size_t i = 0; i < std::max(ma.size(), mb.size()); ++i) {
    if (i >= mb.size()) return true;  // a has a further valid mark
    if (i >= ma.size()) return false;
    if (ma[i] != mb[i]) return ma[i] > mb[i];
  }
  return false;
}

HeightSeries::HeightSeries(std::vector<double> heights, int tries_per_height)
    : heights_(std::move(heights)), tries_per_height_(tries_per_height) {
  if (heights_.empty() || tries_per_height_ < 1)
    throw std::invalid_argument("HeightSeries: give at least one height and one try per height");
}

void HeightSeries::record(bool cleared) {
  if (!jumping()) return;
  ++attempts_;
  if (cleared) {
    best_ = bar_height();
    failures_at_best_ = failures_here_;
    cleared_here_ = true;
    if (height_index_ + 1 == heights_.size()) done_ = true;
    return;
  }
  ++total_failures_;
  if (++failures_here_ >= tries_per_height_) done_ = true;
}

void HeightSeries::raise() {
  if (!waiting())
    throw std::logic_error("HeightSeries::raise: the athlete has not cleared the bar's height");
  ++height_index_;
  failures_here_ = 0;
  cleared_here_ = false;
}

bool ranks_before(const HeightSeries& a, const HeightSeries& b) {
  if (a.best() != b.best()) return a.best() > b.best();
  if (a.best() == 0) return false;  // neither cleared a height: they share the place
  if (a.failures_at_best() != b.failures_at_best())
    return a.failures_at_best() < b.failures_at_best();
  return a.total_failures() < b.total_failures();
}

}  // namespace olympics::sports::athletics
