// The scripted baseline for the hurdles (docs/athletics.md, "Hurdles"): a walker that pushes
// each hurdle over with its hands as it walks through it, and steps over it where it lies.
// Knocking hurdles over is legal under official rules (TR 22.7); under the seed's (fixed walls,
// a touch ends the run) it stops at the first hurdle. It reads only the observation, by name:
// the goal (the finish line's point on its lane's centre) and the hurdles' top bars.
#pragma once

#include <cmath>
#include <optional>

#include "arm_control.h"
#include "policies.h"
#include "step_controller.h"

namespace olympics::client {

class ScriptedHurdlesPolicy : public Policy {
 public:
  void start(const MatchInfo& match) override;
  void act(std::span<const float> observation, std::span<float> action) override;

 private:
  // Both hands on the next hurdle's top bar, pushing it along the arc it falls on.
  void push_bar(std::span<const float> o, std::span<float> a, const Eigen::Vector3d& bar,
                const Eigen::Vector3d& forward);
  // Both arms held forward and a little down (where a standing bar meets the hands).
  void carry_arms(std::span<const float> o, std::span<float> a, const Eigen::Vector3d& forward);

  // The first seconds, while the arms rise slowly.
  bool raising() const { return tick_ < std::lround(kRaiseFor_s / control_dt_); }

  static constexpr double kRaiseFor_s = 3.0;  // raised at once, they topple the walker

  int goal_ = 0, first_ = 0;  // where the goal and the first hurdle start in the observation
  double control_dt_ = 0;
  std::optional<StepController> legs_;
  std::optional<ArmDirection> left_, right_;
  long tick_ = 0;
  double bar_height_ = 0;  // the standing hurdles' top above the ground (1.067 or 0.838 m)
  double upper_arm_ = 0;   // shoulder to elbow, m (read from the first observation)
  double forearm_ = 0;     // elbow to the palm, m
  double push_s_ = 0;      // how long the hands have been on the current bar
};

}  // namespace olympics::client
