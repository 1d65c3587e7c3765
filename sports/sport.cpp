#include "sport.h"

namespace olympics::sports {

int Layout::observation_size() const {
  int n = 0;
  for (const auto& b : observation) n += b.size;
  return n;
}

int Layout::action_size() const {
  int n = 0;
  for (const auto& b : action) n += b.size;
  return n;
}

}  // namespace olympics::sports
