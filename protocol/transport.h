// LCM with what the protocol needs around it: raw and decoded subscriptions (undecodable packets
// are counted, and can be answered with an error instead of silently dropped), signing and
// checking of every message with a deployment secret, thread-safe publishing, and, for tests,
// injected datagram loss.
#pragma once

#include <algorithm>
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

#include "auth.h"
#include "freshness.h"
#include "rate_limit.h"
#include "wire_check.h"

namespace olympics::protocol {

struct TransportOptions {
  TransportOptions(std::string lcm_url = "", double drop = 0.0, std::uint64_t seed = 1,
                   std::shared_ptr<const Authenticator> authenticator = nullptr)
      : url(std::move(lcm_url)), drop_rate(drop), drop_seed(seed), auth(std::move(authenticator)) {}
  std::string url;         // empty: kDefaultLcmUrl
  double drop_rate = 0.0;  // test flag: share of published messages silently dropped
  std::uint64_t drop_seed = 1;
  // With a deployment secret, every message sent is signed and every message received must be:
  // unsigned and forged ones are dropped and counted (unauthenticated()), and so are signed ones
  // received before or sent too long ago (replayed(), stale(); freshness.h). Without one,
  // nothing is signed or checked (loopback experiments only).
  std::shared_ptr<const Authenticator> auth;
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
  // The messages of one type on a channel, decoded (checked, decode()): a well-formed one reaches
  // `handler`; anything else is counted (malformed()) and goes to `on_malformed` when given.
  template <typename Msg>
  int subscribe_to(const std::string& channel,
                   std::function<void(const std::string& channel, const Msg& msg)> handler,
                   RawHandler on_malformed = nullptr);
  void unsubscribe(int handle);

  template <typename Msg>
  void publish(const std::string& channel, const Msg& msg);
  void publish_raw(const std::string& channel, const std::uint8_t* data, int size);
  // Sends without a signature (its field zeroed), even with a secret: for answers to
  // unauthenticated input. What a server signs, clients believe; an answer that echoes ids an
  // outsider chose must not be believable, or the outsider could end any client's match by
  // naming it (docs/security.md, "signed-error oracle"). Receivers with the secret drop it;
  // a client without one (the misconfigured one it is meant for) reads it.
  template <typename Msg>
  void publish_unsigned(const std::string& channel, const Msg& msg);

  // Handles at most one message, waiting up to timeout_ms; returns true if one was handled.
  bool handle(int timeout_ms);
  long published() const { return published_; }
  long dropped() const { return dropped_; }
  // Received messages refused: they did not decode (truncated, corrupt, another version).
  long malformed() const { return malformed_; }
  // Received messages dropped for a missing or wrong signature (with a secret only).
  long unauthenticated() const { return unauthenticated_; }
  // Signed messages dropped because this process took them already (or one so much newer from
  // the same sender that the old one is out of its window): replays (with a secret only).
  long replayed() const { return replayed_; }
  // Signed messages dropped because they were sent more than kMaxMessageAgeMs ago (or ahead) by
  // their sender's clock: replays of old traffic, or hosts whose clocks are apart.
  long stale() const { return stale_; }
  bool authenticating() const { return auth_ != nullptr; }
  // Called (on the receiving thread) for each unauthenticated message dropped.
  void on_unauthenticated(RawHandler handler) { on_unauthenticated_ = std::move(handler); }
  void count_malformed() { ++malformed_; }
  // Whether an answer to bad input (a MALFORMED error) may go out now: at most 20 a second from
  // one process, so that a flood of bad datagrams is not answered by a flood of errors.
  bool may_complain() { return complaints_.allow(); }
  const std::string& url() const { return url_; }

 private:
  struct Subscription;
  std::string url_;
  lcm::LCM lcm_;
  double drop_rate_;
  std::mt19937_64 drop_rng_;
  std::mutex publish_mutex_;
  std::atomic<long> published_{0}, dropped_{0}, malformed_{0}, unauthenticated_{0};
  std::atomic<long> replayed_{0}, stale_{0};
  std::shared_ptr<const Authenticator> auth_;
  RawHandler on_unauthenticated_;
  std::vector<std::uint8_t> signing_buffer_;  // under publish_mutex_
  const std::uint64_t boot_;                  // this process's sender id (freshness.h)
  std::uint64_t next_seq_ = 1;                // under publish_mutex_
  void send(const std::string& channel, const std::uint8_t* data, int size, bool sign);
  // Whether a received datagram may reach the handlers: with a secret, signed and fresh
  // (freshness.h); dropped and counted else.
  bool admit(const std::string& channel, const std::uint8_t* data, int size);
  bool fresh(const std::uint8_t* data, int size);
  ReplayWindows windows_;
  std::optional<bool> dispatch_verdict_;  // admit() of the datagram handle() dispatches now
  LogThrottle replay_log_, stale_log_;
  std::vector<std::unique_ptr<Subscription>> subscriptions_;
  RateLimiter complaints_{20};
};

// The multicast TTL an LCM URL sets (its "ttl=N"; LCM's default, 0, when it names none): above 0
// its messages leave the host and anyone on the LAN can read and send them.
int multicast_ttl(const std::string& url);

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

// The bytes of an LCM message.
template <typename Msg>
std::vector<std::uint8_t> encode(const Msg& msg) {
  std::vector<std::uint8_t> buf(msg.getEncodedSize());
  msg.encode(buf.data(), 0, static_cast<int>(buf.size()));
  return buf;
}

template <typename Msg>
int Transport::subscribe_to(const std::string& channel,
                            std::function<void(const std::string&, const Msg&)> handler,
                            RawHandler on_malformed) {
  return subscribe(channel,
                   [this, handler = std::move(handler), on_malformed = std::move(on_malformed)](
                       const std::string& ch, const std::uint8_t* data, int size) {
                     if (auto msg = decode<Msg>(data, size)) return handler(ch, *msg);
                     count_malformed();
                     if (on_malformed) on_malformed(ch, data, size);
                   });
}

template <typename Msg>
void Transport::publish(const std::string& channel, const Msg& msg) {
  const auto buf = encode(msg);
  publish_raw(channel, buf.data(), static_cast<int>(buf.size()));
}

template <typename Msg>
void Transport::publish_unsigned(const std::string& channel, const Msg& msg) {
  auto buf = encode(msg);
  if (buf.size() < static_cast<size_t>(kSignatureBytes)) return;
  std::fill(buf.end() - kSignatureBytes, buf.end(), std::uint8_t{0});
  send(channel, buf.data(), static_cast<int>(buf.size()), /*sign=*/false);
}

}  // namespace olympics::protocol
