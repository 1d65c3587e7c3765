// The scripted free-throw shooter for basketball (SMPL-X): the yardstick learned shooters must
// beat. A two-handed underhand set shot (the "granny shot"), from the observation alone:
//
// - cradle: both arms forward and down, rolled palms up, elbows and fingers bent up, so the
//   presented ball lies in the cup of the two hands and is held there by its weight and by
//   friction (nothing else holds it: the server has no grip);
// - shot: at `shot_s` both arms swing up in the vertical plane through the rim as fast as their
//   drives allow (a step of their targets) to `release_elevation`, elbows and fingers closing;
//   the ball leaves the hands as they slow down. How far it flies is set by that elevation,
//   where it flies by the plane of the swing, turned to the rim's bearing.
// The legs keep the root over the feet. The numbers were found by search (docs/basketball.md).
#pragma once

#include "policies.h"

namespace olympics::client {

struct FreeThrowShot {
  double hold_elevation = -0.431;    // rad: the arms below the horizontal while cradling
  double hold_elbow = 0.471;         // rad: the elbows bent up under the ball
  double palm_roll = 2.82;           // rad: the forearms rolled palm up, tilted in to a cup
  double wrist_up = 0.0;             // rad: the hands bent back, fingers up
  double finger_curl = 0.183;        // rad per finger joint: the cup
  double hands_apart = -0.251;       // rad: each arm turned out from the rim's direction
  double under = 0.082;              // rad: how far below the hold the hands come in
  double shot_s = 0.95;              // s from the start: the swing
  double shot_curl = 0.559;          // rad: the fingers close in the swing
  double release_elevation = 2.596;  // rad above the horizontal: where the arms stop
  double aim_offset = 0.008;         // rad added to the rim's bearing (the swing pulls aside)
  double shot_elbow = 0.492;         // rad: the elbows in the swing
  // Standing balance: ankle pitch per m of the root ahead of the ankles and per m/s, its bias
  // (the arms and ball ahead of the body), hip pitch per m.
  double ankle_p = 1.0, ankle_d = 2.0, ankle_bias = 0.0, hip_p = 1.0;
};

class ScriptedBasketballPolicy : public Policy {
 public:
  explicit ScriptedBasketballPolicy(const FreeThrowShot& shot = {}) : shot_(shot) {}
  void start(const MatchInfo& match) override;
  void act(std::span<const float> observation, std::span<float> action) override;

 private:
  FreeThrowShot shot_;
  int rim_ = 0;
  double control_dt_ = 0;
  double clock_s_ = 0;
};

}  // namespace olympics::client
