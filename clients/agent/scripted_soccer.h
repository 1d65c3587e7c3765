// The scripted baseline for soccer: the yardstick learned players must beat. It reads only the
// observation (blocks by name):
//
// - the chaser (in 1v1 and the penalty kick always; in 2v2 whichever of the two is nearer the
//   ball) walks (StepController) to a point behind the ball on the line from the goal it attacks
//   through the ball, going round the ball when it stands on the wrong side;
// - lined up behind the ball, it walks through it towards the goal: its swinging feet knock the
//   ball on, a dribble that ends in a shot when the feet meet the ball at speed;
// - in 2v2 the other player stays between the ball and its own goal;
// - while the other side has a restart to take, both keep back from the ball.
#pragma once

#include <optional>

#include "policies.h"
#include "step_controller.h"

namespace olympics::client {

class ScriptedSoccerPolicy : public Policy {
 public:
  void start(const MatchInfo& match) override;
  void act(std::span<const float> observation, std::span<float> action) override;

 private:
  struct Blocks {  // where the fields it reads start (teammate: the first's position; -1: none)
    int ball = 0, goal = 0, own_goal = 0, mate = -1, restart = 0;
  };
  Blocks blocks_;
  std::optional<StepController> legs_;
  bool lined_up_ = false;  // behind the ball and facing the goal: pushing it on
};

}  // namespace olympics::client
