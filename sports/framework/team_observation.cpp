#include "framework/team_observation.h"

#include <string>

namespace olympics::sports {
namespace {

// How many players share `slot`'s team, `team_of` giving each slot's.
template <typename TeamOf>
int teammates(int slots, int slot, const TeamOf& team_of) {
  int n = 0;
  for (int s = 0; s < slots; ++s) n += s != slot && team_of(s) == team_of(slot);
  return n;
}

// The fields of the k-th player of a block.
std::string position_field(int k) { return "position_" + std::to_string(k); }
std::string velocity_field(int k) { return "velocity_" + std::to_string(k); }

// Position and velocity of `players` players, in order.
std::vector<FieldSize> player_fields(int players) {
  std::vector<FieldSize> fields;
  for (int k = 0; k < players; ++k)
    fields.push_back({position_field(k), 3}), fields.push_back({velocity_field(k), 3});
  return fields;
}

}  // namespace

void append_team_blocks(const ModeSpec& mode, std::vector<LayoutBlock>& blocks) {
  const int mates = teammates(mode.slot_count(), 0, [&](int s) { return mode.slot_teams[s]; });
  const int opponents = mode.slot_count() - mates - 1;
  if (mates > 0)
    blocks.push_back(LayoutBlock::of(
        "teammates", "m, m/s",
        "each teammate's root position (3) and velocity (3), heading frame, in slot order",
        player_fields(mates)));
  if (opponents > 0)
    blocks.push_back(LayoutBlock::of(
        "opponents", "m, m/s",
        "each opponent's root position (3) and velocity (3), heading frame, in slot order",
        player_fields(opponents)));
}

void write_team_blocks(const SmplMatch& match, int slot, const HeadingFrame& frame,
                       ObservationWriter& out) {
  const auto others = [&](bool same_team) {
    int k = 0;
    for (int s = 0; s < match.slot_count(); ++s) {
      if (s == slot || (match.team_of(s) == match.team_of(slot)) != same_team) continue;
      const core::BodyState st = match.scene().humanoid(s).body_state(0);
      out.field(position_field(k)).put(frame.point(st.position));
      out.field(velocity_field(k++)).put(frame.vector(st.linear_velocity));
    }
  };
  const int mates = teammates(match.slot_count(), slot, [&](int s) { return match.team_of(s); });
  if (mates > 0) others((out.begin("teammates"), true));
  if (match.slot_count() - mates - 1 > 0) others((out.begin("opponents"), false));
}

}  // namespace olympics::sports
