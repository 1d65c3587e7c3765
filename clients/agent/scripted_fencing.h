// The scripted baseline for fencing: the yardstick learned fencers must beat. It reads only the
// observation (blocks by name, all in read_view), and is built on the control toolkit
// (docs/control.md):
//
// - on guard it faces the opponent with the épée in line, the tip held on the line from the
//   shoulder to the opponent's chest by the arm's IK with gravity compensation, the trunk held
//   up, and its centre of mass balanced over its feet;
// - footwork keeps it just out of the opponent's reach (stepping back when the other comes in,
//   never further back than its end of the piste allows);
// - it attacks: the arm extends first, the tip driven to the chest and a little beyond, then the
//   legs step in until the tip lands (its touch count goes up) or the attack has gone on too
//   long;
// - it recovers: the arm back on guard, a step back out of reach, and on guard again.
#pragma once

#include <memory>
#include <optional>

#include "policies.h"
#include "step_controller.h"

namespace olympics::client {

class ScriptedFencingPolicy : public Policy {
 public:
  ScriptedFencingPolicy();
  ~ScriptedFencingPolicy() override;
  void start(const MatchInfo& match) override;
  void act(std::span<const float> observation, std::span<float> action) override;

 private:
  struct Blocks {
    int opponent_root = 0, opponent_targets = 0, piste = 0, bout = 0;
  };
  struct View;  // what the policy reads of one observation
  struct Arm;   // the body model and the épée arm's IK
  enum class Phase { Guard, Attack, Recover };

  View read_view(std::span<const float> o) const;

  Blocks blocks_;
  double control_dt_ = 0;
  std::unique_ptr<Arm> arm_;
  std::optional<StepController> legs_;
  Phase phase_ = Phase::Guard;
  double phase_s_ = 0;
  double touches_ = 0;  // my touches as last seen: an increase means the attack landed
  bool have_tip_goal_ = false;
  Eigen::Vector3d tip_goal_{0, 0, 0};
};

}  // namespace olympics::client
