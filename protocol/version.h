// Protocol and software versions.
#pragma once

#include <optional>
#include <string>

#include "olympics/protocol_version_t.hpp"

namespace olympics::protocol {

inline constexpr int kProtocolVersion = olympics::protocol_version_t::VERSION;
inline constexpr const char* kSoftwareVersion = "0.1.0";

// nullopt when `version` is ours; else the message for an UPGRADE error.
std::optional<std::string> version_mismatch(int version);

}  // namespace olympics::protocol
