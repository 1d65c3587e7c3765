// Where each field of the humanoid's self observation lies, for a humanoid of B bodies
// (HUMANOID.md section 2): the one description the server writes it by
// (core/self_observation.cpp) and the clients read it by (clients/agent/smpl_observation.h,
// smplx_observation.h). Header-only and free of dependencies, so that both ends include it.
//
//   root_height          1      the root's height
//   body_positions       3(B-1) bodies 1..B-1 minus the root position
//   body_rotations       6B     each body's x axis then z axis (tan-norm 6D)
//   linear_velocities    3B     each body's, the root first
//   angular_velocities   3B     each body's, the root first
//
// Every vector is in the root's heading frame. B comes from the loaded model on the server, and
// from the announced size of the "self" block on a client (for_size()).
#pragma once

#include <array>
#include <stdexcept>
#include <string>
#include <string_view>

namespace olympics::core {

struct SelfObservationField {
  std::string_view name;
  int offset;
  int size;
};

struct SelfObservationLayout {
  int bodies;

  constexpr int size() const { return angular_velocities() + 3 * bodies; }
  constexpr int root_height() const { return 0; }
  constexpr int body_positions() const { return 1; }
  constexpr int body_rotations() const { return body_positions() + 3 * (bodies - 1); }
  constexpr int linear_velocities() const { return body_rotations() + 6 * bodies; }
  constexpr int angular_velocities() const { return linear_velocities() + 3 * bodies; }

  // Where body `body`'s entries start in each field (body_position: body >= 1, the root is the
  // origin).
  constexpr int body_position(int body) const { return body_positions() + 3 * (body - 1); }
  constexpr int body_rotation(int body) const { return body_rotations() + 6 * body; }
  // A body's rotation is its x axis (3) then its z axis (3).
  constexpr int body_x_axis(int body) const { return body_rotation(body); }
  constexpr int body_z_axis(int body) const { return body_rotation(body) + 3; }
  constexpr int linear_velocity(int body) const { return linear_velocities() + 3 * body; }
  constexpr int angular_velocity(int body) const { return angular_velocities() + 3 * body; }

  constexpr std::array<SelfObservationField, 5> fields() const {
    return {{{"root_height", root_height(), 1},
             {"body_positions", body_positions(), 3 * (bodies - 1)},
             {"body_rotations", body_rotations(), 6 * bodies},
             {"linear_velocities", linear_velocities(), 3 * bodies},
             {"angular_velocities", angular_velocities(), 3 * bodies}}};
  }
  // The field called `name`; throws std::invalid_argument naming the fields there are.
  SelfObservationField field(std::string_view name) const {
    for (const auto& f : fields())
      if (f.name == name) return f;
    std::string known;
    for (const auto& f : fields()) known += (known.empty() ? "" : ", ") + std::string(f.name);
    throw std::invalid_argument("the self observation has no field \"" + std::string(name) +
                                "\"; its fields: " + known);
  }

  // The layout whose size is `size` (15 B - 2 floats); throws std::invalid_argument when no body
  // count gives it.
  static SelfObservationLayout for_size(int size) {
    const SelfObservationLayout l{(size + 2) / 15};
    if (l.bodies < 1 || l.size() != size)
      throw std::invalid_argument("a self observation of " + std::to_string(size) +
                                  " floats is not 15 x bodies - 2: not a humanoid's");
    return l;
  }
};

}  // namespace olympics::core
