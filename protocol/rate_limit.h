// At most `per_second` events a second, in bursts of up to that many (a token bucket): answers to
// bad input are rate-limited so that a flood of bad datagrams cannot make a process flood the
// network with errors in return.
#pragma once

#include <algorithm>
#include <chrono>
#include <mutex>

namespace olympics::protocol {

class RateLimiter {
 public:
  explicit RateLimiter(double per_second) : rate_(per_second), tokens_(per_second) {}
  // Whether one more event may go now; counts it if so.
  bool allow() {
    std::lock_guard lock(mutex_);
    const auto now = std::chrono::steady_clock::now();
    tokens_ = std::min(rate_, tokens_ + rate_ * std::chrono::duration<double>(now - last_).count());
    last_ = now;
    if (tokens_ < 1) return false;
    tokens_ -= 1;
    return true;
  }

 private:
  std::mutex mutex_;
  double rate_, tokens_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// At most one log line a second for one kind of event, so that a flood of bad or replayed
// datagrams cannot fill a disk with lines: note() counts an event and, when a line is due, says
// how many it covers (the events suppressed since the last line, this one included); 0 else.
class LogThrottle {
 public:
  long note() {
    std::lock_guard lock(mutex_);
    ++pending_;
    const auto now = std::chrono::steady_clock::now();
    if (logged_once_ && now - last_ < std::chrono::seconds(1)) return 0;
    logged_once_ = true;
    last_ = now;
    const long n = pending_;
    pending_ = 0;
    return n;
  }

 private:
  std::mutex mutex_;
  long pending_ = 0;
  bool logged_once_ = false;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace olympics::protocol
