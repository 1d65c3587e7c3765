#include "framework/team_observation.h"

#include <algorithm>

namespace olympics::sports {
namespace {

int teammates_of_slot_0(const ModeSpec& mode) {
  return static_cast<int>(
             std::count(mode.slot_teams.begin(), mode.slot_teams.end(), mode.slot_teams[0])) -
         1;
}

}  // namespace

void append_team_blocks(const ModeSpec& mode, std::vector<LayoutBlock>& blocks) {
  const int teammates = teammates_of_slot_0(mode);
  const int opponents = mode.slot_count() - teammates - 1;
  if (teammates > 0)
    blocks.push_back({"teammates", 6 * teammates, "m, m/s",
                      "each teammate's root position (3) and velocity (3), heading frame, in slot "
                      "order"});
  if (opponents > 0)
    blocks.push_back({"opponents", 6 * opponents, "m, m/s",
                      "each opponent's root position (3) and velocity (3), heading frame, in slot "
                      "order"});
}

void write_team_blocks(const SmplMatch& match, int slot, const HeadingFrame& frame,
                       ObservationWriter& out) {
  const auto others = [&](bool same_team) {
    for (int s = 0; s < match.slot_count(); ++s) {
      if (s == slot || (match.team_of(s) == match.team_of(slot)) != same_team) continue;
      const core::BodyState st = match.scene().humanoid(s).body_state(0);
      out.put(frame.point(st.position)).put(frame.vector(st.linear_velocity));
    }
  };
  int teammates = 0;
  for (int s = 0; s < match.slot_count(); ++s)
    teammates += s != slot && match.team_of(s) == match.team_of(slot);
  if (teammates > 0) others((out.begin("teammates"), true));
  if (match.slot_count() - teammates - 1 > 0) others((out.begin("opponents"), false));
}

}  // namespace olympics::sports
