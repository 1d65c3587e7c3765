// Small pieces the benchmarks share.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "core/control_rate.h"
#include "match_info.h"
#include "sport.h"

namespace olympics::bench {

// What a policy is told of a match played in process (the server tells remote clients the same
// through match_created_t).
inline client::MatchInfo in_process_match_info(const std::string& sport, const std::string& mode,
                                               const sports::SportMatch& match) {
  return {sport, mode, core::kControlDt,
          client::ObservationLayout::from_blocks(match.layout().observation), match.action_size()};
}

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace olympics::bench
