// Match replays: the seed and every applied action per tick, enough to re-run a match and prove
// that it reproduces the recorded result and final physical state bit for bit.
//
// File format (`<match_id>.replay`): the line "OLYMPICS-REPLAY 1", one line of JSON (the header:
// sport, mode, seed, time limit, slot teams, forfeit if any, and the result with the final state
// hash), then ticks x slots x action_size little-endian float32 values.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace olympics::server {

struct Replay {
  nlohmann::json header;
  int slot_count = 0;
  int action_size = 0;
  std::vector<float> actions;  // tick-major, then slot, then action entry
  int ticks() const {
    return slot_count && action_size ? static_cast<int>(actions.size()) / (slot_count * action_size)
                                     : 0;
  }
};

// Writes the replay at `path`, or, if that file exists, beside it with a numbered suffix (a
// replay is never overwritten); returns where it went.
std::string write_replay(const std::string& path, const Replay& replay);
// Throws std::runtime_error naming the file and what is wrong with it.
Replay read_replay(const std::string& path);

struct ReplayCheck {
  bool identical = false;
  std::string report;  // what was compared and what differed
};
// Re-runs the match from the replay and compares ticks, reason, winner, scores and state hash.
ReplayCheck verify_replay(const Replay& replay);

}  // namespace olympics::server
