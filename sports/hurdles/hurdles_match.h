// A hurdles race: one lane per athlete, side by side in one scene, ten hurdles in each (free
// hurdles that tip over, or the seed's fixed walls); every athlete starts at once from its start
// mark and the referee decides each one's race (a finish with its time, did not finish, or
// disqualified); the match ends when every race is decided, or at the time limit, and ranks the
// athletes by time.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "framework/smpl_match.h"
#include "hurdles/hurdle.h"
#include "hurdles/hurdles_rules.h"
#include "hurdles/race_referee.h"

namespace olympics::sports::hurdles {

inline constexpr int kHurdles = 10;  // in both races (TR 22.1)

std::vector<LayoutBlock> hurdles_task_layout();
std::vector<RefereeCall> hurdles_calls();

class HurdlesMatch : public SmplMatch {
 public:
  HurdlesMatch(const HurdlesRules& rules, const ModeSpec& mode, Layout layout,
               const MatchSettings& settings);

  const HurdlesRules& rules() const { return rules_; }
  double lane_y(int slot) const { return slot * rules_.lane_spacing; }
  // The race's result for the athlete (nullopt: still racing).
  const std::optional<RaceResult>& result(int slot) const { return athletes_[slot].result; }
  int knocked(int slot) const { return athletes_[slot].knocked; }
  // Tests: the athlete's humanoid and its lane's free hurdles (official), to set a scene up.
  core::Humanoid& athlete(int slot) { return player(slot); }
  Hurdle& hurdle(int slot, int i) { return *lanes_[slot].hurdles.at(i); }

 private:
  struct Athlete {
    explicit Athlete(const HurdlesRules& rules) : referee(rules) {}
    RaceReferee referee;
    std::optional<RaceResult> result = std::nullopt;
    Eigen::Vector3d root_prev = Eigen::Vector3d::Zero();         // the last physics step's
    Eigen::Vector3d reward_root_prev = Eigen::Vector3d::Zero();  // the last tick's
    double torso_front_prev = -1e9;
    std::vector<Eigen::Vector3d> legs_prev;  // the leg bodies' positions, the last step
    int knocked = 0;
    bool announced = false;  // its result has been called
  };
  struct Lane {
    std::vector<std::unique_ptr<Hurdle>> hurdles;  // official: free bodies
    std::vector<bool> counted;                     // knocked over and counted
    std::vector<const core::GeomTag*> walls;       // paper: fixed sensing walls
  };

  void write_task_observation(int slot, const HeadingFrame& frame,
                              ObservationWriter& out) const override;
  void after_physics_step(double step_start) override;
  void settle_tick() override;
  void on_time_limit() override;
  void extra_state(std::vector<double>& values) const override;
  void describe_scene(SceneBuilder& scene) const override;
  void extra_scene_poses(std::vector<float>& out) const override;

  void build_lane(int slot);
  RaceStep read_step(int slot, double step_start);
  bool touched_a_wall(int slot) const;
  bool trail_leg_beside(int slot, const std::vector<Eigen::Vector3d>& legs) const;
  double torso_front_x(int slot) const;
  std::vector<Eigen::Vector3d> leg_positions(int slot) const;
  Eigen::Vector3d hurdle_top(int slot, int i) const;
  Eigen::Vector3d goal(int slot) const { return {rules_.race_m, lane_y(slot), rules_.goal_z}; }
  void count_knocked(int slot);
  void wake_hurdles_near_athletes();
  void announce(int slot);
  void finish(const std::string& why);

  HurdlesRules rules_;
  std::vector<Athlete> athletes_;
  std::vector<Lane> lanes_;
  std::vector<int> torso_, legs_, feet_;  // body indices
};

}  // namespace olympics::sports::hurdles
