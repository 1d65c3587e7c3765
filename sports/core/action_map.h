// Policy action -> PD targets, as the original's isaac_pd mode does it.
//
// target_i = scale_i * a_i, scale_i = min(1.2 * max(|lo_i|, |hi_i|), pi) from the hinge range
// (pi when the file gives none), and 5 for the knee-flexion hinges (the hinge of a body named
// "*Knee*" whose axis is the body's lateral y axis). Actions are not clipped: any finite value
// is accepted; non-finite values are refused with std::invalid_argument.
#pragma once

#include <span>
#include <vector>

#include "core/model_spec.h"

namespace olympics::core {

class ActionMap {
 public:
  explicit ActionMap(const ModelSpec& spec);
  int size() const { return static_cast<int>(scales_.size()); }
  const std::vector<double>& scales() const { return scales_; }
  // Writes size() targets into out; throws on a wrong size or a NaN/Inf entry.
  void targets(std::span<const float> action, std::span<double> out) const;

 private:
  std::vector<double> scales_;
};

}  // namespace olympics::core
