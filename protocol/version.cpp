#include "version.h"

namespace olympics::protocol {

std::optional<std::string> version_mismatch(int version) {
  if (version == kProtocolVersion) return std::nullopt;
  return "protocol version " + std::to_string(version) + " is not spoken here (this side speaks " +
         std::to_string(kProtocolVersion) + "); upgrade the " +
         (version < kProtocolVersion ? "client" : "server") + " to protocol " +
         std::to_string(std::max(version, kProtocolVersion));
}

}  // namespace olympics::protocol
