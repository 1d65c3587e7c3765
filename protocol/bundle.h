// Bundles (bundle_t): many matches' encoded messages in one datagram. A vector client sends its
// action batches for every match on one server as one bundle per tick, and each server worker
// sends each client one bundle of the observation batches its pass produced, instead of one
// datagram per match: the datagrams (and the kernel's copies of each to every socket on the
// port) drop by the number of matches in a bundle. A bundle stays under kMaxMessageBytes; more
// parts than fit go in the next bundle.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "olympics/bundle_t.hpp"

namespace olympics::protocol {

class BundleWriter {
 public:
  explicit BundleWriter(std::string client_id);
  // One encoded message of match `match_id`.
  void add(const std::string& match_id, std::span<const std::uint8_t> part);
  bool empty() const { return bundles_.empty(); }
  // The encoded bundles so far, each under kMaxMessageBytes (a single part bigger than that
  // travels alone); the writer is empty afterwards.
  std::vector<std::vector<std::uint8_t>> take();

 private:
  std::string client_id_;
  std::vector<olympics::bundle_t> bundles_;
  int open_size_ = 0;  // the encoded size of bundles_.back()
};

// Calls `part` for each part of a received bundle; false (and no call) when its sizes and
// counts disagree.
bool for_each_part(const olympics::bundle_t& bundle,
                   const std::function<void(const std::string& match_id, const std::uint8_t* data,
                                            int size)>& part);

}  // namespace olympics::protocol
