// One server worker's observation batches for the clients that bundle (they sent their last
// actions in a bundle, protocol/bundle.h): collected while the worker passes over its matches,
// then sent as one bundle per client (or as few as fit a datagram) instead of one datagram per
// match. Used by its worker thread only.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <string>

#include "bundle.h"
#include "transport.h"

namespace olympics::server {

class ObservationOutbox {
 public:
  void add(const std::string& client_id, const std::string& match_id,
           std::span<const std::uint8_t> batch);
  bool empty() const { return by_client_.empty(); }
  // Sends what was added since the last flush.
  void flush(protocol::Transport& transport);

 private:
  std::map<std::string, protocol::BundleWriter> by_client_;
};

}  // namespace olympics::server
