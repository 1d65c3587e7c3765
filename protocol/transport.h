// LCM with what the protocol needs around it: raw subscriptions (so undecodable packets can be
// answered with an error instead of silently dropped), thread-safe publishing, and, for tests,
// injected datagram loss.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <lcm/lcm-cpp.hpp>
#include <memory>
#include <mutex>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "wire_check.h"

namespace olympics::protocol {

struct TransportOptions {
  std::string url;         // empty: kDefaultLcmUrl
  double drop_rate = 0.0;  // test flag: share of published messages silently dropped
  std::uint64_t drop_seed = 1;
};

class Transport {
 public:
  // Throws std::runtime_error saying how to fix the multicast route when LCM cannot start.
  explicit Transport(const TransportOptions& options = {});
  ~Transport();

  using RawHandler =
      std::function<void(const std::string& channel, const std::uint8_t* data, int size)>;
  // channel is a regular expression, as in LCM. Returns a handle for unsubscribe().
  int subscribe(const std::string& channel, RawHandler handler);
  void unsubscribe(int handle);

  template <typename Msg>
  void publish(const std::string& channel, const Msg& msg);
  void publish_raw(const std::string& channel, const std::uint8_t* data, int size);

  // Handles at most one message, waiting up to timeout_ms; returns true if one was handled.
  bool handle(int timeout_ms);
  long published() const { return published_; }
  long dropped() const { return dropped_; }
  const std::string& url() const { return url_; }

 private:
  struct Subscription;
  std::string url_;
  lcm::LCM lcm_;
  double drop_rate_;
  std::mt19937_64 drop_rng_;
  std::mutex publish_mutex_;
  std::atomic<long> published_{0}, dropped_{0};
  std::vector<std::unique_ptr<Subscription>> subscriptions_;
};

// The bytes of an LCM message.
template <typename Msg>
std::vector<std::uint8_t> encode(const Msg& msg) {
  std::vector<std::uint8_t> buf(msg.getEncodedSize());
  msg.encode(buf.data(), 0, static_cast<int>(buf.size()));
  return buf;
}

template <typename Msg>
void Transport::publish(const std::string& channel, const Msg& msg) {
  const auto buf = encode(msg);
  publish_raw(channel, buf.data(), static_cast<int>(buf.size()));
}

// Decodes an LCM message; nullopt when the bytes are truncated, corrupt, or of another type or
// version. It cannot crash or allocate without bound: the bytes are checked against the type's
// layout first (wire_check.h), and anything the decoder still throws is caught.
template <typename Msg>
std::optional<Msg> decode(const std::uint8_t* data, int size) {
  if (wire_problem(Msg::getTypeName(), Msg::getHash(), data, size)) return std::nullopt;
  Msg msg;
  try {
    if (msg.decode(data, 0, size) < 0) return std::nullopt;
  } catch (...) {
    return std::nullopt;
  }
  return msg;
}

}  // namespace olympics::protocol
