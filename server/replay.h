// Match replays: the seed and every applied action per tick, enough to re-run a match and prove
// that it reproduces the recorded result and final physical state bit for bit.
//
// File format (`<match_id>.replay`): the line "OLYMPICS-REPLAY 1", one line of JSON (the header:
// sport, mode, seed, time limit, slot teams, forfeit if any, and the result with the final state
// hash), then ticks x slots x action_size little-endian float32 values.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sport.h"

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
// Re-runs the match from the replay, calling `on_tick` (if given) before the first tick and
// after every tick (and after a recorded forfeit); returns the match as it ends. Throws
// std::runtime_error when the replay does not fit its sport.
std::unique_ptr<sports::SportMatch> rerun_replay(
    const Replay& replay, const std::function<void(const sports::SportMatch&)>& on_tick);

// Re-runs the match from the replay and compares ticks, reason, winner, scores and state hash.
ReplayCheck verify_replay(const Replay& replay);

}  // namespace olympics::server
