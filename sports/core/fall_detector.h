// Fall detection (SPORTS.md, shared pieces): a body other than the feet and toes (and, in
// sports with equipment, the hand that holds it) touches the ground or drops below 0.15 m.
// The first two ticks after a reset are not checked, as in the original.
#pragma once

#include <string>
#include <vector>

#include "core/humanoid.h"

namespace olympics::core {

class FallDetector {
 public:
  explicit FallDetector(const ModelSpec& spec, std::vector<std::string> extra_contact_bodies = {});
  void reset() { ticks_since_reset_ = 0; }
  // Call once per control tick, after stepping; reads and clears the humanoid's ground flags.
  bool fallen(Humanoid& humanoid);
  // Name of the body that caused the last fall, for logs and match results.
  const std::string& culprit() const { return culprit_; }

  static constexpr double kMinHeight = 0.15;

 private:
  std::vector<bool> may_touch_;  // per body: feet, toes, equipment hand
  int ticks_since_reset_ = 0;
  std::string culprit_;
};

}  // namespace olympics::core
