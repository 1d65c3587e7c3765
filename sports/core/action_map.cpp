#include "core/action_map.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace olympics::core {

ActionMap::ActionMap(const ModelSpec& spec) {
  for (const auto& body : spec.bodies) {
    bool knee = body.name.find("Knee") != std::string::npos;
    for (const auto& h : body.hinges) {
      double reach = std::max(std::abs(h.range_lo), std::abs(h.range_hi));
      double scale = reach > 0 ? std::min(1.2 * reach, M_PI) : M_PI;
      if (knee && std::abs(h.axis.y()) > 0.99) scale = 5.0;
      scales_.push_back(scale);
    }
  }
}

void ActionMap::targets(std::span<const float> action, std::span<double> out) const {
  if (action.size() != scales_.size())
    throw std::invalid_argument("action has " + std::to_string(action.size()) +
                                " numbers; this humanoid takes " + std::to_string(scales_.size()));
  for (size_t i = 0; i < scales_.size(); ++i) {
    if (!std::isfinite(action[i]))
      throw std::invalid_argument("action[" + std::to_string(i) + "] is not finite (NaN or Inf)");
    out[i] = scales_[i] * static_cast<double>(action[i]);
  }
}

}  // namespace olympics::core
