// A javelin match of SMPL-X athletes (fingers: 153 joint targets): per athlete a runway ending in
// an 8 m arc and a landing sector (official), the javelin in its right hand, held at the cord by
// a grip joint while its fingers are closed; each athlete's series of attempts taken one after
// another from its start mark, side by side lane_spacing apart; the match ends when every series
// is complete and ranks the athletes (best valid mark, then the next best, TR 25.22).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "athletics/attempt_series.h"
#include "framework/smpl_match.h"
#include "javelin/javelin_implement.h"
#include "javelin/javelin_referee.h"
#include "javelin/javelin_rules.h"
#include "javelin/throwing_area.h"
#include "javelin/throwing_hand.h"

namespace olympics::sports::javelin {

// The humanoid the javelin plays, chosen here once: the SMPL-X, whose fingers hold the javelin.
inline constexpr core::HumanoidKind kHumanoid = core::HumanoidKind::SmplX;

std::vector<LayoutBlock> javelin_task_layout();
std::vector<RefereeCall> javelin_calls();

class JavelinMatch : public SmplMatch {
 public:
  JavelinMatch(const JavelinRules& rules, const ModeSpec& mode, Layout layout,
               const MatchSettings& settings);

  const JavelinRules& rules() const { return rules_; }
  const athletics::HorizontalSeries& series(int slot) const { return athletes_[slot].series; }
  double lane_y(int slot) const { return slot * rules_.lane_spacing; }
  ThrowingArea area(int slot) const;
  // Tests and baselines: the athlete's humanoid and javelin.
  core::Humanoid& athlete(int slot) { return player(slot); }
  Javelin& javelin(int slot) { return *athletes_[slot].javelin; }
  const Javelin& javelin(int slot) const { return *athletes_[slot].javelin; }
  // The seed's default attitude: forward along the runway, tilted default_pitch_deg up.
  Eigen::Quaterniond default_attitude() const;

 private:
  struct Athlete {
    Athlete(int attempts, JavelinReferee r, std::unique_ptr<Javelin> j, ThrowingHand h)
        : series(attempts), referee(r), javelin(std::move(j)), hand(h) {}
    athletics::HorizontalSeries series;
    JavelinReferee referee;
    std::unique_ptr<Javelin> javelin;
    ThrowingHand hand;
    double attempt_start = 0;
    int attempt_tick = 0;  // the match tick the attempt began at
    double present_until = 0;
    std::optional<athletics::AttemptResult> decided;  // this step's decision, acted on in settle
    Eigen::Vector3d cord_start = Eigen::Vector3d::Zero();
    Eigen::Vector2d root_start = Eigen::Vector2d::Zero();
    double javelin_x_prev = 0;
  };

  void write_task_observation(int slot, const HeadingFrame& frame,
                              ObservationWriter& out) const override;
  void before_physics_step() override;
  void after_physics_step(double step_start) override;
  void settle_tick() override;
  void on_time_limit() override;
  void describe_scene(SceneBuilder& scene) const override;
  void extra_scene_poses(std::vector<float>& out) const override;
  void extra_state(std::vector<double>& values) const override;

  core::RootPlacement start_mark(int slot) const { return {{0.0, lane_y(slot), 0.0}, 0.0}; }
  // The athlete on its mark, the javelin in its hand at the default attitude, a new attempt.
  void begin_attempt(int slot);
  ThrowStep read_step(int slot) const;
  int attempt_tick(int slot) const { return tick() - athletes_[slot].attempt_tick; }
  void finish();

  JavelinRules rules_;
  std::vector<Athlete> athletes_;
};

}  // namespace olympics::sports::javelin
