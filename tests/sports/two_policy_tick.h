// One tick of an in-process two-slot match between two policies (the basketball players' tests).
#pragma once

#include <span>
#include <vector>

#include "sport.h"

namespace olympics::sports {

// Each slot observes and its policy acts, then the match steps. `Players` holds a pointer-like
// to each slot's policy (a unique_ptr or a raw pointer).
template <typename Players>
void two_policy_tick(SportMatch& m, Players& players, std::vector<float> (&obs)[2],
                     std::vector<float> (&act)[2]) {
  for (int s = 0; s < 2; ++s) {
    obs[s].resize(m.obs_size()), act[s].resize(m.action_size());
    m.observe(s, obs[s]);
    players[s]->act(obs[s], act[s]);
  }
  m.step({std::span<const float>(act[0]), std::span<const float>(act[1])});
}

}  // namespace olympics::sports
