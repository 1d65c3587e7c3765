// Shape and value checks of incoming messages. Every refusal names what was wrong and what to do.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "olympics/action_batch_t.hpp"

namespace olympics::protocol {

struct ProtocolError {
  std::string code;     // BAD_ACTION, UNKNOWN_SLOT, UPGRADE, ...
  std::string message;  // what was wrong and what to do
};

// An action batch for a match with `slot_count` slots of `action_size` floats, from a client that
// owns `owned_slots`. Checks version, sizes, slot ownership (at least one slot, none twice) and
// that every value is finite.
std::optional<ProtocolError> check_action_batch(const olympics::action_batch_t& batch,
                                                int slot_count, int action_size,
                                                const std::vector<int>& owned_slots);

}  // namespace olympics::protocol
