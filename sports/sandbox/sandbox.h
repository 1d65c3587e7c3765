// The sandbox sport: flat ground, 1-4 SMPL humanoids, a time limit, fall detection.
//
// Rules: every standing humanoid earns its team one point per second. A humanoid that falls is
// out for the rest of the match (done = true for its slot). The match ends at the time limit
// ("time_limit"), when every humanoid has fallen ("all_fell"), or, with several teams, when the
// humanoids still standing all belong to one team ("last_team_standing"). The team with the most
// points wins; equal points are a draw.
//
// Rewards per tick: alive (+1 while standing), fall (-1 on the tick of the fall).
// Task observation, after the 358 self-observation floats: time remaining (fraction of the
// limit), then for every other slot in slot order: its root position and root velocity in this
// humanoid's heading frame, and 1 if it has fallen.
#pragma once

#include <random>

#include "core/fall_detector.h"
#include "core/humanoid_scene.h"
#include "sport.h"

namespace olympics::sports {

class SandboxSport : public Sport {
 public:
  std::string name() const override { return "sandbox"; }
  std::string summary() const override {
    return "flat ground, 1-4 humanoids; stay standing longest (fall detection, time limit)";
  }
  std::vector<std::string> modes() const override;
  double default_time_limit_s() const override { return 20.0; }
  std::unique_ptr<SportMatch> create(const MatchSettings& settings) const override;
  Layout layout(const std::string& mode) const override;
};

class SandboxMatch : public SportMatch {
 public:
  SandboxMatch(std::vector<int> slot_teams, const MatchSettings& settings);

  int slot_count() const override { return static_cast<int>(teams_.size()); }
  int team_count() const override { return team_count_; }
  int team_of(int slot) const override { return teams_[slot]; }
  int obs_size() const override;
  int action_size() const override { return 69; }
  const std::vector<std::string>& reward_terms() const override { return terms_; }
  void observe(int slot, std::span<float> out) const override;
  void step(const std::vector<std::span<const float>>& actions) override;
  const TickOutcome& outcome() const override { return outcome_; }
  int tick() const override { return tick_; }
  void forfeit(int losing_team, const std::string& reason) override;
  std::uint64_t state_hash() const override;

 private:
  void decide_end();

  std::vector<int> teams_;
  int team_count_ = 0;
  int time_limit_ticks_;
  core::HumanoidScene scene_;
  std::vector<core::FallDetector> falls_;
  std::vector<std::uint8_t> fallen_;
  std::vector<std::string> terms_{"alive", "fall"};
  TickOutcome outcome_;
  int tick_ = 0;
};

}  // namespace olympics::sports
