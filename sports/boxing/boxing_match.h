// A boxing bout (1v1): two SMPL boxers with gloves in a roped ring. Scoring punches are found at
// the physics rate from the gloves' contacts: blows (BlowSensor: a glove arriving fast, knuckles
// first; never a glove resting or pushing), filtered (a target body, front or side, hard enough,
// nobody down); the BoxingReferee runs rounds, counts and cards. Rewards: the seed's
// eq. 9-10 with the nearer glove as the striker (combat_rewards.h).
#pragma once

#include <array>
#include <optional>
#include <random>

#include "boxing/blows.h"
#include "boxing/boxing_referee.h"
#include "boxing/ring.h"
#include "framework/smpl_match.h"

namespace olympics::sports::boxing {

struct BoxingConfig {
  BoxingRules rules;
  Ring ring;
  bool both_gloves = true;          // false: the seed's right glove only
  double punch_force_n = 100;       // a blow's contact force, in its first step, that scores
  BlowRules blows;                  // what makes a glove's arrival a blow
  double punch_refractory_s = 0.3;  // one glove scores at most this often
};

// Does a punch on this body score? The seed's targets (combat_observation.h) less the pelvis:
// it is below the belt, where a blow is a foul, never a point (AIBA's and the professional
// rules). The pelvis stays in the observation and in eq. 9-10's r_strike, as the seed has them.
bool scores_punch_on(const std::string& body);

// The SMPL humanoid with gloves on both hands, or on the right only.
const core::ModelSpec& boxer_model(bool both_gloves);

std::vector<LayoutBlock> boxing_task_layout();
std::vector<RefereeCall> boxing_calls();
// Does a punch whose contact normal (from the target towards the glove) is `normal` land from
// the front or the side of a defender turned `defender`? Not within 60 degrees of straight
// behind it.
bool from_front_or_side(const Eigen::Vector3d& normal, const Eigen::Quaterniond& defender);

// The time a whole bout takes: every round and rest, and a few seconds to spare.
double bout_length_s(const BoxingRules& rules);

class BoxingMatch : public SmplMatch {
 public:
  BoxingMatch(const BoxingConfig& config, const ModeSpec& mode, Layout layout,
              const MatchSettings& settings);

  const BoxingReferee& referee() const { return referee_; }
  // The slot whose boxer was created first in the physics world (drawn per bout).
  int created_first() const { return created_first_; }
  // Every arrival of a glove on the opponent so far, blows or not, scoring or not.
  const std::vector<GloveArrival>& arrivals() const { return arrivals_; }
  // Where a boxer's glove is (or its bare hand, when not gloved), in the world.
  Eigen::Vector3d glove_position(int slot, int hand) const;  // hand 0 left, 1 right

 private:
  void write_task_observation(int slot, const HeadingFrame& frame,
                              ObservationWriter& out) const override;
  void before_physics_step() override;
  void after_physics_step(double step_start) override;
  bool scores(const GloveArrival& a) const;
  void settle_tick() override;
  void on_time_limit() override;
  void describe_scene(SceneBuilder& scene) const override { config_.ring.describe(scene); }

  void log_calls();
  void back_to_corners();
  core::RootPlacement corner(int boxer);
  nlohmann::json score_json() const;

  BoxingConfig config_;
  std::array<int, 2> hands_{};                   // L_Hand, R_Hand
  std::array<Eigen::Vector3d, 2> glove_centre_;  // in each hand's frame
  std::vector<int> targets_;
  BoxingReferee referee_;
  int created_first_ = 0;
  std::vector<bool> scoring_body_;  // by body index: a punch there scores
  std::optional<BlowSensor> blows_;
  std::array<std::array<double, 2>, 2> last_scored_;  // [slot][hand], s
  std::vector<GloveArrival> arrivals_;
  std::array<bool, 2> scored_this_tick_{};
  nlohmann::json rounds_ = nlohmann::json::array();  // every round's card, for the result
};

}  // namespace olympics::sports::boxing
