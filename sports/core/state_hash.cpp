#include "core/state_hash.h"

#include <xxhash.h>

namespace olympics::core {

void append_body_state(dBodyID body, std::vector<double>& values) {
  values.insert(values.end(), dBodyGetPosition(body), dBodyGetPosition(body) + 3);
  values.insert(values.end(), dBodyGetQuaternion(body), dBodyGetQuaternion(body) + 4);
  values.insert(values.end(), dBodyGetLinearVel(body), dBodyGetLinearVel(body) + 3);
  values.insert(values.end(), dBodyGetAngularVel(body), dBodyGetAngularVel(body) + 3);
}

std::uint64_t state_hash(const HumanoidScene& scene, std::span<const double> extra) {
  std::vector<double> values;
  for (int i = 0; i < scene.humanoid_count(); ++i)
    for (int b = 0; b < scene.humanoid(i).body_count(); ++b)
      append_body_state(scene.humanoid(i).ode_body(b), values);
  values.insert(values.end(), extra.begin(), extra.end());
  return XXH3_64bits(values.data(), values.size() * sizeof(double));
}

}  // namespace olympics::core
