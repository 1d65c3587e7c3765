#include "basketball/basket_watch.h"

namespace olympics::sports::basketball {

RimPassage BasketWatch::step(const Eigen::Vector3d& before, const Eigen::Vector3d& after) {
  RimPassage out;
  if (const int b = court_.basket_from_below(before, after); b >= 0) {
    came_up_[b] = true;
    out.from_below = b;
    return out;
  }
  const bool down_through_plane = before.z() >= court_.rim_height && after.z() < court_.rim_height;
  if (!down_through_plane) return out;
  const int b = court_.basket_through(before, after);
  if (b >= 0 && !came_up_[b]) out.basket = b;
  reset();
  return out;
}

}  // namespace olympics::sports::basketball
