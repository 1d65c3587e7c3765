// Freshness of signed messages (docs/security.md, "Replays"). A signature proves who sent a
// message, not when: anyone who reads a datagram can send it again. So the signed trailer of
// every message starts with the sender's freshness: a random id of the sending process (its
// boot), a sequence number that grows with each message it sends, and its clock when it sent.
// A receiver keeps, per sender boot, a window of the sequence numbers it took and drops any
// message it has taken already or that is older than the window, and any message sent more
// than kMaxMessageAgeMs ago (or as far in the future): a replay from an earlier boot, or of a
// message whose window a receiver has forgotten, is stale by then.
#pragma once

#include <bitset>
#include <cstdint>
#include <mutex>
#include <unordered_map>

namespace olympics::protocol {

struct Freshness {
  std::uint64_t boot = 0;    // random per sending process (Transport), never 0
  std::uint64_t seq = 0;     // 1, 2, ... per boot
  std::int64_t sent_ms = 0;  // the sender's wall clock, Unix milliseconds
};
// 24 bytes, big-endian, at the start of the signature field.
void write_freshness(std::uint8_t* out, const Freshness& f);
Freshness read_freshness(const std::uint8_t* in);

// How old a message may be when it arrives: the hosts of a deployment must keep their clocks
// closer than this (NTP does by far). Longer than any wait of the protocol between a message
// and its answer; a request is resent (fresh) every 250 ms while it matters.
inline constexpr std::int64_t kMaxMessageAgeMs = 10'000;

// Unix milliseconds now.
std::int64_t wall_clock_ms();

class ReplayWindows {
 public:
  enum class Verdict { Fresh, Replayed, Stale };
  // Whether the message with this freshness is new here; if so it is remembered.
  Verdict admit(const Freshness& f, std::int64_t now_ms);
  size_t senders() const;

 private:
  // Sequence numbers this far below the highest seen are refused: UDP on one host keeps order,
  // so the width only has to cover reordering on a network.
  static constexpr std::uint64_t kWidth = 1024;
  struct Window {
    std::uint64_t highest = 0;
    std::bitset<kWidth> seen;  // bit d: highest - d was taken
    std::int64_t last_ms = 0;  // when this receiver last took one
  };
  mutable std::mutex mutex_;
  std::unordered_map<std::uint64_t, Window> windows_;
  std::int64_t next_sweep_ms_ = 0;
};

}  // namespace olympics::protocol
