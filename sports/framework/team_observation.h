// The "teammates" and "opponents" observation blocks of team play (soccer, basketball): their
// layout entries and their writer in one place.
#pragma once

#include <vector>

#include "framework/heading_frame.h"
#include "framework/observation_writer.h"
#include "framework/smpl_match.h"
#include "sport.h"

namespace olympics::sports {

// Appends "teammates" (when the mode has any) and "opponents" (when it has any): each other
// player's root position (3) and velocity (3), heading frame, in slot order (fields position_0,
// velocity_0, position_1, ...: the k-th other player of the block).
void append_team_blocks(const ModeSpec& mode, std::vector<LayoutBlock>& blocks);
// Writes the blocks append_team_blocks added for the match's mode, seen from `slot`.
void write_team_blocks(const SmplMatch& match, int slot, const HeadingFrame& frame,
                       ObservationWriter& out);

}  // namespace olympics::sports
