// Reads a humanoid from an MJCF file (the subset that SMPL-style humanoids use).
//
// Supported: <compiler angle coordinate="local">, <option timestep>, <default> classes,
// one root body with a free joint, bodies with pos/quat/euler/axisangle, 0 or 3 hinge joints at
// the body origin, sphere/capsule/cylinder/box geoms (size or fromto, density or mass, friction),
// PD gains from a joint's `user` field (kp kd ...) or else its stiffness/damping, and
// <contact><exclude>. Files written y-up (SMPL's native frame) are turned z-up.
// Anything else that would change the humanoid raises MjcfError naming file, line, element and
// problem; purely visual elements (lights, textures, sites, actuators) are ignored.
#pragma once

#include <stdexcept>
#include <string>

#include "core/model_spec.h"

namespace olympics::core {

class MjcfError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class UpAxis { Auto, Z, Y };

struct MjcfLoadOptions {
  // Auto: y-up when the body named like "Head" sits along +y from the root, else z-up.
  UpAxis up = UpAxis::Auto;
};

ModelSpec load_mjcf_file(const std::string& path, const MjcfLoadOptions& options = {});
ModelSpec load_mjcf_string(const std::string& xml, const std::string& name_for_errors,
                           const MjcfLoadOptions& options = {});

}  // namespace olympics::core
