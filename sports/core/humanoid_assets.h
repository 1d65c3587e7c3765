// Where the project's humanoid MJCF files are, and loading them by kind.
#pragma once

#include <string>

#include "core/model_spec.h"

namespace olympics::core {

enum class HumanoidKind { Smpl, SmplX };

// Directory of the bundled assets: $OLYMPICS_ASSET_DIR if set, else the source tree's
// sports/core/assets (baked in at build time).
std::string asset_directory();
std::string humanoid_asset_path(HumanoidKind kind);
ModelSpec load_humanoid(HumanoidKind kind);

}  // namespace olympics::core
