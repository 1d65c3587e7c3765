#include "freshness.h"

#include <chrono>

namespace olympics::protocol {
namespace {
void put64(std::uint8_t* out, std::uint64_t v) {
  for (int i = 7; i >= 0; --i, v >>= 8) out[i] = static_cast<std::uint8_t>(v & 0xff);
}
std::uint64_t get64(const std::uint8_t* in) {
  std::uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v = (v << 8) | in[i];
  return v;
}
}  // namespace

void write_freshness(std::uint8_t* out, const Freshness& f) {
  put64(out, f.boot);
  put64(out + 8, f.seq);
  put64(out + 16, static_cast<std::uint64_t>(f.sent_ms));
}

Freshness read_freshness(const std::uint8_t* in) {
  return {get64(in), get64(in + 8), static_cast<std::int64_t>(get64(in + 16))};
}

std::int64_t wall_clock_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

ReplayWindows::Verdict ReplayWindows::admit(const Freshness& f, std::int64_t now_ms) {
  if (f.boot == 0 || f.seq == 0 || f.sent_ms < now_ms - kMaxMessageAgeMs ||
      f.sent_ms > now_ms + kMaxMessageAgeMs)
    return Verdict::Stale;
  std::lock_guard lock(mutex_);
  if (now_ms >= next_sweep_ms_) {
    // A sender unheard for twice the age limit: anything it sent that is still fresh was never
    // taken here, so its window can go.
    std::erase_if(windows_,
                  [&](const auto& w) { return w.second.last_ms < now_ms - 2 * kMaxMessageAgeMs; });
    next_sweep_ms_ = now_ms + 1000;
  }
  Window& w = windows_[f.boot];
  if (f.seq > w.highest) {
    const std::uint64_t shift = f.seq - w.highest;
    if (shift >= kWidth)
      w.seen.reset();
    else
      w.seen <<= shift;
    w.highest = f.seq;
    w.seen.set(0);
  } else {
    const std::uint64_t behind = w.highest - f.seq;
    if (behind >= kWidth || w.seen.test(behind)) return Verdict::Replayed;
    w.seen.set(behind);
  }
  w.last_ms = now_ms;
  return Verdict::Fresh;
}

size_t ReplayWindows::senders() const {
  std::lock_guard lock(mutex_);
  return windows_.size();
}

}  // namespace olympics::protocol
