// Channel names of the wire protocol (docs/protocol.md).
#pragma once

#include <string>

namespace olympics::protocol {

inline constexpr const char* kAnnounce = "OLY_ANNOUNCE";
inline constexpr const char* kRequest = "OLY_REQUEST";
inline constexpr const char* kCreated = "OLY_CREATED";
inline constexpr const char* kJoin = "OLY_JOIN";
inline constexpr const char* kJoinReply = "OLY_JOIN_REPLY";
inline constexpr const char* kStart = "OLY_START";
inline constexpr const char* kResult = "OLY_RESULT";
inline constexpr const char* kError = "OLY_ERROR";
inline constexpr const char* kHeartbeat = "OLY_HEARTBEAT";
inline constexpr const char* kLeague = "OLY_LEAGUE";
inline constexpr const char* kObsPrefix = "OLY_OBS_";
inline constexpr const char* kActPrefix = "OLY_ACT_";

inline std::string obs_channel(const std::string& match_id) { return kObsPrefix + match_id; }
inline std::string action_channel(const std::string& match_id) { return kActPrefix + match_id; }

// Bundles (bundle_t): a client's actions for every match it plays on one server, and one server
// worker's observations for one client, each in as few datagrams as fit.
inline constexpr const char* kActionBundlePrefix = "OLY_BACT_";
inline constexpr const char* kObsBundlePrefix = "OLY_BOBS_";
inline std::string action_bundle_channel(const std::string& server_id) {
  return kActionBundlePrefix + server_id;
}
inline std::string obs_bundle_channel(const std::string& client_id) {
  return kObsBundlePrefix + client_id;
}

// Loopback multicast with a 4 MB receive buffer: the default for one machine.
inline constexpr const char* kDefaultLcmUrl =
    "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304";

// A message must fit one UDP datagram: LCM fragments bigger ones, and a lost fragment loses all.
inline constexpr int kMaxMessageBytes = 64000;

}  // namespace olympics::protocol
