// Playing a match in process with zero actions, and reading its events and observation blocks
// (the sports' match tests).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "match_info.h"
#include "sport.h"

namespace olympics::sports {

// One tick with zero actions; the tick's events.
inline nlohmann::json step_zero(SportMatch& m) {
  std::vector<float> zero(m.action_size(), 0.0f);
  std::vector<std::span<const float>> actions(m.slot_count(), zero);
  m.step(actions);
  return m.outcome().info["events"];
}

// Zero-action ticks until the match ends (at most `ticks`); every tick's events, in order.
inline nlohmann::json play_zero(SportMatch& m, int ticks) {
  nlohmann::json events = nlohmann::json::array();
  for (int t = 0; t < ticks && !m.outcome().match_over; ++t)
    for (const auto& e : step_zero(m)) events.push_back(e);
  return events;
}

// The first event of `call` among `events`, or nullptr.
inline const nlohmann::json* find_call(const nlohmann::json& events, const std::string& call) {
  for (const auto& e : events)
    if (e["call"] == call) return &e;
  return nullptr;
}

// Where the observation block `name` starts (throws naming the blocks there are).
inline int block_offset(const SportMatch& m, const std::string& name) {
  return client::ObservationLayout::from_blocks(m.layout().observation).offset(name);
}
// Where field `field` of block `block` starts (throws naming the block's fields).
inline int field_offset(const SportMatch& m, const std::string& block, const std::string& field) {
  return client::ObservationLayout::from_blocks(m.layout().observation).offset(block, field);
}

}  // namespace olympics::sports
