#include "core/humanoid_assets.h"

#include <cstdlib>

#include "core/mjcf_loader.h"

#ifndef OLYMPICS_ASSET_DIR
#error "OLYMPICS_ASSET_DIR must be defined by the build"
#endif

namespace olympics::core {

std::string asset_directory() {
  if (const char* dir = std::getenv("OLYMPICS_ASSET_DIR"); dir && *dir) return dir;
  return OLYMPICS_ASSET_DIR;
}

std::string humanoid_asset_path(HumanoidKind kind) {
  return asset_directory() +
         (kind == HumanoidKind::Smpl ? "/smpl_humanoid.xml" : "/smplx_humanoid.xml");
}

ModelSpec load_humanoid(HumanoidKind kind) { return load_mjcf_file(humanoid_asset_path(kind)); }

}  // namespace olympics::core
