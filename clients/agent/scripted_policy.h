// The scripted baseline for tennis and table tennis (`--policy scripted`): the yardstick that
// learned policies must beat. It reads only the observation (docs/protocol.md layouts):
//
// - balance: ankle and hip pitch/roll targets from where the root is over the ankles and how it
//   moves (a stiff ankle strategy; gains found by search, standing > 20 s when undisturbed);
// - reach: the ball's path is predicted (gravity, one bounce on the court or table) to where it
//   crosses a plane just in front of the player; the right arm points the racket there, with the
//   face turned to the net;
// - swing: the arm is drawn back while the ball is far and swung through as it arrives.
//
// It does not walk: the humanoid stays where the point starts and reaches. Which sport it plays
// it tells from the observation (the court surface height).
#pragma once

#include "policies.h"

namespace olympics::client {

class ScriptedRacketPolicy : public Policy {
 public:
  void act(std::span<const float> observation, std::span<float> action) override;
};

}  // namespace olympics::client
