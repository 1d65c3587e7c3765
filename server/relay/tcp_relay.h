// One cell's LCM traffic over one TCP connection (docs/deploy.md, "Remote learners"). LCM's
// multicast stays inside each host (ttl=0); the relay on the cell host listens on a TCP port, the
// relay on the learner's host connects to it, and each side republishes on its own LCM URL
// every message the other side heard, so a trainer's client on the learner's host plays matches
// on the cell's server as if it were there. Messages are carried as they are (signed by their
// senders); the connection itself is admitted only for a peer that proves it holds the
// deployment's secret (an HMAC of a fresh challenge, both ways).
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

namespace olympics::protocol {
class Authenticator;
}

namespace olympics::relay {

struct RelaySettings {
  std::string lcm_url;  // this host's side ("" = the project's default URL)
  std::shared_ptr<const protocol::Authenticator> auth;  // required: the deployment's secret
};

struct RelayCounts {
  std::atomic<std::uint64_t> sent{0}, received{0};  // messages to and from the peer
};

// Cell side: accepts one learner at a time on `port` (of `bind_address`) and relays until it
// goes; then the next. Returns only on an error it cannot go on after (throws).
void serve(const RelaySettings& settings, const std::string& bind_address, int port,
           RelayCounts& counts);

// Learner side: connects to the cell's relay at host:port and relays until the connection ends
// (returns) or `stop` is set. Throws with what went wrong (refused, wrong secret, unreachable).
void connect_and_relay(const RelaySettings& settings, const std::string& host, int port,
                       RelayCounts& counts, const std::atomic<bool>& stop);

}  // namespace olympics::relay
