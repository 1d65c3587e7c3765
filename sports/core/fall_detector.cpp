#include "core/fall_detector.h"

#include <algorithm>

namespace olympics::core {

FallDetector::FallDetector(const ModelSpec& spec, std::vector<std::string> extra_contact_bodies) {
  for (const auto& b : spec.bodies) {
    bool foot =
        b.name.find("Ankle") != std::string::npos || b.name.find("Toe") != std::string::npos;
    bool extra = std::find(extra_contact_bodies.begin(), extra_contact_bodies.end(), b.name) !=
                 extra_contact_bodies.end();
    may_touch_.push_back(foot || extra);
  }
}

bool FallDetector::fallen(Humanoid& humanoid) {
  bool checked = ++ticks_since_reset_ > 2;
  bool fell = false;
  for (int i = 0; checked && i < humanoid.body_count() && !fell; ++i) {
    if (may_touch_[i]) continue;
    if (humanoid.touched_ground(i) || humanoid.body_state(i).position.z() < kMinHeight) {
      fell = true;
      culprit_ = humanoid.spec().bodies[i].name;
    }
  }
  humanoid.clear_ground_contacts();
  return fell;
}

}  // namespace olympics::core
