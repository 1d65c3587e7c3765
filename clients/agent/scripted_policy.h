// The scripted baseline for tennis and table tennis (`--policy scripted`): the yardstick that
// learned policies must beat. It reads only the observation (docs/protocol.md layouts):
//
// - prediction: the ball's path is stepped forward (gravity, one bounce on the court or table) to
//   where it crosses a plane just in front of the player;
// - moving: while the ball comes to its side, a StepController walks the player sideways so that
//   point falls under the racket, and turns it back to face the net; otherwise it stands (ankle
//   and hip balance) or walks back toward the middle of its half;
// - reach and swing: the right arm points the racket at the crossing point with the face turned
//   to the net, drawn back while the ball is far and swung through as it arrives.
//
// Which sport it plays it tells from the observation (the court surface height).
#pragma once

#include <optional>

#include "policies.h"
#include "step_controller.h"

namespace olympics::client {

class ScriptedRacketPolicy : public Policy {
 public:
  void act(std::span<const float> observation, std::span<float> action) override;

 private:
  std::optional<StepController> legs_;
  bool legs_for_table_ = false;
};

}  // namespace olympics::client
