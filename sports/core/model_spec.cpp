#include "core/model_spec.h"

namespace olympics::core {

int ModelSpec::body_index(const std::string& name) const {
  for (size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].name == name) return static_cast<int>(i);
  return -1;
}

int ModelSpec::dof_count() const {
  int n = 0;
  for (const auto& b : bodies) n += static_cast<int>(b.hinges.size());
  return n;
}

std::vector<std::string> ModelSpec::hinge_names() const {
  std::vector<std::string> names;
  for (const auto& b : bodies)
    for (const auto& h : b.hinges) names.push_back(h.name);
  return names;
}

}  // namespace olympics::core
