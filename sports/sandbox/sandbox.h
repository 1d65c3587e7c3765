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

#include "framework/smpl_match.h"
#include "sport.h"

namespace olympics::sports {

class SandboxSport : public Sport {
 public:
  SandboxSport();
  std::string name() const override { return "sandbox"; }
  std::string summary() const override {
    return "flat ground, 1-4 humanoids; stay standing longest (fall detection, time limit)";
  }
  const ModeTable& modes() const override { return modes_; }
  double default_time_limit_s() const override { return 20.0; }
  std::unique_ptr<SportMatch> create(const MatchSettings& settings) const override;
  Layout layout(const std::string& mode) const override;

 private:
  ModeTable modes_;
};

class SandboxMatch : public SmplMatch {
 public:
  SandboxMatch(const ModeSpec& mode, Layout layout, const MatchSettings& settings);

 private:
  void write_task_observation(int slot, const HeadingFrame& frame,
                              ObservationWriter& out) const override;
  void settle_tick() override;

  std::vector<std::uint8_t> fallen_;
};

}  // namespace olympics::sports
