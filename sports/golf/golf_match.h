// A golf match: one lane per athlete, side by side (lane_spacing apart, so shots never meet),
// each with its own ball and, by the official rules, its own hole; every athlete plays its hole
// (the seed's one shot) at once, and the match ends when all are over and ranks them: fewest
// strokes first (official), or the ball stopped nearest the target first (paper).
#pragma once

#include <memory>
#include <vector>

#include "equipment/ball.h"
#include "framework/smpl_match.h"
#include "golf/golf_green.h"
#include "golf/golf_referee.h"
#include "golf/golf_rules.h"
#include "golf/swept_strike.h"

namespace olympics::sports::golf {

std::vector<LayoutBlock> golf_task_layout();
std::vector<RefereeCall> golf_calls();

// The Rules of Golf's ball: at most 45.93 g, at least 42.67 mm across; e 0.1 and friction 1 on
// the ground (the original's ball), air drag as equipment::Ball's.
equipment::BallSpec rules_golf_ball();

class GolfMatch : public SmplMatch {
 public:
  GolfMatch(const GolfRules& rules, const ModeSpec& mode, Layout layout,
            const MatchSettings& settings);

  const GolfRules& rules() const { return rules_; }
  // Tests and benches: an athlete's ball, hole (official), referee, target.
  equipment::Ball& ball(int slot) { return *athletes_[slot].ball; }
  const equipment::Ball& ball(int slot) const { return *athletes_[slot].ball; }
  const Hole* hole(int slot) const { return athletes_[slot].hole.get(); }
  const HoleReferee& hole_referee(int slot) const { return athletes_[slot].hole_ref; }
  const SeedReferee& seed_referee(int slot) const { return athletes_[slot].seed_ref; }
  Eigen::Vector3d target(int slot) const { return athletes_[slot].target; }
  Eigen::Vector3d club_head(int slot) const;
  equipment::Pose club_head_pose(int slot) const;
  core::Humanoid& athlete(int slot) { return player(slot); }
  int hand_body() const { return hand_body_; }

 private:
  struct Athlete {
    std::unique_ptr<equipment::Ball> ball;
    std::unique_ptr<Hole> hole;
    Eigen::Vector3d origin;  // where the ball starts (the lane's origin)
    Eigen::Vector3d target;  // the hole's centre or the seed's target, z = 0
    Eigen::Vector3d ball_prev;
    Eigen::Vector3d lie;  // where the ball was last at rest: the next stroke is played from it
    HoleReferee hole_ref;
    SeedReferee seed_ref;
    double start = 0;  // when the hole began
    int start_tick = 0;
    bool touched = false;  // the club touched the ball in this tick
    double touched_t = 0;
    bool over = false;
    // At the start of the physics step: for the swept strike of a fast head (swept_strike.h).
    equipment::Pose head_before;
    Eigen::Vector3d ball_before = Eigen::Vector3d::Zero();
  };

  void write_task_observation(int slot, const HeadingFrame& frame,
                              ObservationWriter& out) const override;
  void before_physics_step() override;
  void after_physics_step(double step_start) override;
  void settle_tick() override;
  void on_time_limit() override;
  void extra_state(std::vector<double>& values) const override;
  void describe_scene(SceneBuilder& scene) const override;
  void extra_scene_poses(std::vector<float>& out) const override;

  Eigen::Vector3d lane_origin(int slot) const;
  core::RootPlacement address(const Athlete& a) const;
  GolfTick read_tick(int slot) const;
  void settle_official(int slot, const GolfTick& t);
  void settle_paper(int slot, const GolfTick& t);
  bool on_green(const Athlete& a) const;
  bool body_near_ball(int slot) const;
  std::vector<int> places() const;
  void finish(const std::string& why);

  GolfRules rules_;
  std::vector<Athlete> athletes_;
  int hand_body_ = -1;
  int club_geoms_from_ = 0;  // the hand's geoms from this index are the club's
  double green_c_rr_ = 0, fairway_c_rr_ = 0;
  GreenSlope slope_;  // the green's (official; every lane's falls the same way)
};

}  // namespace olympics::sports::golf
