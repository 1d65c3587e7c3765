#include "validation.h"

#include <algorithm>
#include <cmath>

#include "version.h"

namespace olympics::protocol {

std::optional<ProtocolError> check_action_batch(const olympics::action_batch_t& b, int slot_count,
                                                int action_size,
                                                const std::vector<int>& owned_slots) {
  if (auto v = version_mismatch(b.protocol_version)) return ProtocolError{"UPGRADE", *v};
  const std::string where = "action batch for tick " + std::to_string(b.tick) + ": ";
  if (b.num_slots != static_cast<int>(b.slots.size()) ||
      b.num_slots != static_cast<int>(b.actions.size()))
    return ProtocolError{"BAD_ACTION", where + "num_slots does not match the arrays"};
  if (b.action_size != action_size)
    return ProtocolError{"BAD_ACTION", where + "action_size is " + std::to_string(b.action_size) +
                                           " but this match takes " + std::to_string(action_size) +
                                           " floats per slot; see `olympics-server describe`"};
  if (b.num_slots == 0)
    return ProtocolError{"BAD_ACTION", where +
                                           "the batch names no slot; send one action for each "
                                           "slot you own (the batch was ignored)"};
  for (int i = 0; i < b.num_slots; ++i) {
    int slot = b.slots[i];
    if (std::find(b.slots.begin(), b.slots.begin() + i, slot) != b.slots.begin() + i)
      return ProtocolError{"BAD_ACTION", where + "slot " + std::to_string(slot) +
                                             " appears twice; send one action per slot (the "
                                             "batch was ignored)"};
    if (slot < 0 || slot >= slot_count)
      return ProtocolError{"UNKNOWN_SLOT", where + "slot " + std::to_string(slot) +
                                               " does not exist (the match has " +
                                               std::to_string(slot_count) + ")"};
    if (std::find(owned_slots.begin(), owned_slots.end(), slot) == owned_slots.end())
      return ProtocolError{"UNKNOWN_SLOT",
                           where + "slot " + std::to_string(slot) + " is not yours; join it first"};
    if (static_cast<int>(b.actions[i].size()) != action_size)
      return ProtocolError{"BAD_ACTION", where + "slot " + std::to_string(slot) + " has " +
                                             std::to_string(b.actions[i].size()) +
                                             " floats, expected " + std::to_string(action_size)};
    for (int k = 0; k < action_size; ++k)
      if (!std::isfinite(b.actions[i][k]))
        return ProtocolError{"BAD_ACTION", where + "slot " + std::to_string(slot) + " action[" +
                                               std::to_string(k) +
                                               "] is NaN or Inf; the batch was ignored and the "
                                               "previous action repeats"};
  }
  return std::nullopt;
}

}  // namespace olympics::protocol
