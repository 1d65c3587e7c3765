#include "core/self_observation.h"

#include <algorithm>
#include <stdexcept>

#include "core/rotation.h"
#include "core/self_observation_layout.h"

namespace olympics::core {

int self_observation_size(int body_count) { return SelfObservationLayout{body_count}.size(); }

void write_self_observation(const std::vector<BodyState>& bodies, std::span<float> out) {
  const int n = static_cast<int>(bodies.size());
  const SelfObservationLayout at{n};
  if (static_cast<int>(out.size()) != at.size())
    throw std::invalid_argument("self observation buffer has the wrong size");
  const BodyState& root = bodies[0];
  const Eigen::Quaterniond heading_inv = inverse_heading(root.orientation);
  auto put = [&](int k, double v) {
    out[k] = std::clamp(static_cast<float>(v), -kObservationClamp, kObservationClamp);
  };
  auto put3 = [&](int k, const Eigen::Vector3d& v) {
    put(k, v.x()), put(k + 1, v.y()), put(k + 2, v.z());
  };
  put(at.root_height(), root.position.z());
  for (int i = 1; i < n; ++i)
    put3(at.body_position(i), heading_inv * (bodies[i].position - root.position));
  for (int i = 0; i < n; ++i) {
    Eigen::Quaterniond local = heading_inv * bodies[i].orientation;
    put3(at.body_rotation(i), local * Eigen::Vector3d::UnitX());
    put3(at.body_rotation(i) + 3, local * Eigen::Vector3d::UnitZ());
  }
  for (int i = 0; i < n; ++i) put3(at.linear_velocity(i), heading_inv * bodies[i].linear_velocity);
  for (int i = 0; i < n; ++i)
    put3(at.angular_velocity(i), heading_inv * bodies[i].angular_velocity);
}

std::vector<std::string> self_observation_names(const ModelSpec& spec) {
  std::vector<std::string> names{"root_height"};
  auto add3 = [&](const std::string& prefix, const std::string& body) {
    for (const char* axis : {"x", "y", "z"}) names.push_back(prefix + "." + body + "." + axis);
  };
  for (size_t i = 1; i < spec.bodies.size(); ++i) add3("pos", spec.bodies[i].name);
  for (const auto& b : spec.bodies) add3("rot_xaxis", b.name), add3("rot_zaxis", b.name);
  for (const auto& b : spec.bodies) add3("linvel", b.name);
  for (const auto& b : spec.bodies) add3("angvel", b.name);
  return names;
}

}  // namespace olympics::core
