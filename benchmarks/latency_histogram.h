// Percentiles of many latencies without keeping them: counts in 0.1 ms bins up to 10 s (longer
// ones land in the last bin; the maximum is kept exactly). An hour of ticks fits in 400 kB.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace olympics::bench {

class LatencyHistogram {
 public:
  void add(double ms) {
    const auto bin = static_cast<std::size_t>(std::max(0.0, ms) / kBinMs);
    ++bins_[std::min(bin, bins_.size() - 1)];
    ++count_;
    max_ms_ = std::max(max_ms_, ms);
  }
  void merge(const LatencyHistogram& other) {
    for (std::size_t i = 0; i < bins_.size(); ++i) bins_[i] += other.bins_[i];
    count_ += other.count_;
    max_ms_ = std::max(max_ms_, other.max_ms_);
  }
  // The upper edge of the bin holding the p-quantile (0 < p <= 1); 0 when empty.
  double percentile_ms(double p) const {
    if (count_ == 0) return 0;
    const auto rank =
        std::min(count_ - 1, static_cast<std::uint64_t>(p * static_cast<double>(count_)));
    std::uint64_t seen = 0;
    std::size_t i = 0;
    while ((seen += bins_[i]) <= rank) ++i;
    return static_cast<double>(i + 1) * kBinMs;
  }
  std::uint64_t count() const { return count_; }
  double max_ms() const { return max_ms_; }

 private:
  static constexpr double kBinMs = 0.1;
  std::vector<std::uint64_t> bins_ = std::vector<std::uint64_t>(100000, 0);
  std::uint64_t count_ = 0;
  double max_ms_ = 0;
};

}  // namespace olympics::bench
