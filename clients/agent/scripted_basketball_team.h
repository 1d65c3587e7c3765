// The scripted basketball team player (1v1, 2v2; SMPL-X), from the observation alone:
//
// - with the ball presented to it at a restart (the `game` block's flag) it is the attacker: it
//   cradles the ball and shoots with the free-throw shooter's set shot (scripted_basketball.h),
//   aimed at the rim by the ballistic solution. Where the rim is beyond the set shot's reach (the
//   solution asks for more than the strongest swing's speed: the check ball's 7.5 m) it shoots
//   the long shot, the strongest swing with the collar bones lifting the arms as well, by as much
//   as the ballistic solution asks (`FreeThrowShot::long_shot`). Where the rim is behind it (the
//   ball taken under the basket after the other side scored, to be cleared behind the arc, which
//   it cannot walk to) it throws the ball ahead, out over the far line: the other side's check
//   ball at once instead of after the 12 s shot clock;
// - otherwise it stands where the restart put it, balanced with gravity compensation
//   (control/standing_balance.h; so too once its shot has left the hands). A defender is put by the
//   match between the attacker and the rim (`restart_distance` in front of the taker), and stays
//   there.
//
// What it does not do, and why (docs/basketball.md, "The scripted team player"): walk. There is
// no SMPL-X locomotion (the stepping controller drives the SMPL humanoid, whose drives are three
// times stiffer), so it cannot drive to the rim, dribble, clear the ball after a basket, chase a
// rebound or follow an attacker.
#pragma once

#include <optional>

#include "control/body_model.h"
#include "scripted_basketball.h"

namespace olympics::client {

class ScriptedBasketballTeamPlayer : public Policy {
 public:
  explicit ScriptedBasketballTeamPlayer(const FreeThrowShot& shot = {}) : shot_(shot) {}
  void start(const MatchInfo& match) override;
  void act(std::span<const float> observation, std::span<float> action) override;

  int shots() const { return shots_; }    // swings started
  int heaves() const { return heaves_; }  // of those, from beyond the set shot's reach: long shots
  int throws_out() const { return throws_out_; }  // of those, thrown out with the rim behind
  bool shooting() const { return shooter_.has_value(); }

  // Seconds from the ball's presentation to the end of a shot's follow-through: the shooter
  // swings at `FreeThrowShot::shot_s` (0.95 s) and the ball is gone a few ticks later.
  static constexpr double kShotPlay_s = 1.6;
  // Seconds after the swing's start by which the ball has left the hands (its third tick, 0.1 s,
  // with margin).
  static constexpr double kRelease_s = 0.2;

 private:
  // Is the rim within the set shot's reach from where the ball is (the ballistic solution's
  // speed no more than the strongest swing's)?
  bool rim_in_reach(std::span<const float> observation) const;

  FreeThrowShot shot_;
  MatchInfo match_;
  control::BodyModel model_ = control::BodyModel::humanoid(core::HumanoidKind::SmplX);
  std::optional<ScriptedBasketballPolicy> shooter_;  // while a shot is on
  double shot_clock_s_ = 0;                          // s since the shot began
  bool was_presented_ = false;
  int ball_ = 0, rim_ = 0, presented_ = 0;
  int shots_ = 0, heaves_ = 0, throws_out_ = 0;
};

}  // namespace olympics::client
