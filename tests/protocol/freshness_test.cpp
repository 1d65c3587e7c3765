// Freshness: a signed message is taken once. The receiver's window per sender boot refuses a
// copy of a message it took, one older than its window, and one sent too long ago (or ahead) by
// the sender's clock; the freshness is signed, so an outsider cannot renew an old message. Over
// real LCM: an attacker without the secret who sends a captured datagram again is not heard,
// while every subscription of the receiver still hears the original once.
#include "freshness.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "auth.h"
#include "channels.h"
#include "olympics/heartbeat_t.hpp"
#include "transport.h"
#include "version.h"

namespace olympics::protocol {
namespace {

using Verdict = ReplayWindows::Verdict;

TEST(Freshness, AMessageIsTakenOnceAndOldOnesAreRefused) {
  ReplayWindows w;
  const std::int64_t now = 1'700'000'000'000;
  EXPECT_EQ(w.admit({7, 1, now}, now), Verdict::Fresh);
  EXPECT_EQ(w.admit({7, 1, now}, now), Verdict::Replayed) << "a copy";
  EXPECT_EQ(w.admit({7, 3, now}, now), Verdict::Fresh) << "a gap";
  EXPECT_EQ(w.admit({7, 2, now}, now), Verdict::Fresh) << "late, inside the window, once";
  EXPECT_EQ(w.admit({7, 2, now}, now), Verdict::Replayed);
  EXPECT_EQ(w.admit({7, 5000, now}, now), Verdict::Fresh);
  EXPECT_EQ(w.admit({7, 4, now}, now), Verdict::Replayed) << "older than the window";
  EXPECT_EQ(w.admit({8, 1, now}, now), Verdict::Fresh) << "another sender boot: its own window";
  EXPECT_EQ(w.admit({9, 1, now - kMaxMessageAgeMs - 1}, now), Verdict::Stale)
      << "sent too long ago";
  EXPECT_EQ(w.admit({9, 1, now + kMaxMessageAgeMs + 1}, now), Verdict::Stale) << "from the future";
  EXPECT_EQ(w.admit({0, 1, now}, now), Verdict::Stale) << "no boot: not one of ours";
  EXPECT_EQ(w.admit({9, 0, now}, now), Verdict::Stale) << "no sequence";
}

TEST(Freshness, SendersUnheardForTwiceTheAgeLimitAreForgotten) {
  ReplayWindows w;
  const std::int64_t t0 = 1'700'000'000'000;
  for (std::uint64_t boot = 1; boot <= 100; ++boot) w.admit({boot, 1, t0}, t0);
  EXPECT_EQ(w.senders(), 100u);
  const std::int64_t later = t0 + 2 * kMaxMessageAgeMs + 1001;
  EXPECT_EQ(w.admit({500, 1, later}, later), Verdict::Fresh);
  EXPECT_EQ(w.senders(), 1u);
}

TEST(Freshness, TheFreshnessTravelsInTheSignedTrailer) {
  std::uint8_t bytes[kFreshnessBytes];
  write_freshness(bytes, {0x0102030405060708ull, 42, 1'700'000'000'123});
  const Freshness f = read_freshness(bytes);
  EXPECT_EQ(f.boot, 0x0102030405060708ull);
  EXPECT_EQ(f.seq, 42u);
  EXPECT_EQ(f.sent_ms, 1'700'000'000'123);
}

std::string lcm_url() {
  return "udpm://239.255.76.67:" + std::to_string(21000 + getpid() % 20000) + "?ttl=0";
}

olympics::heartbeat_t beat() {
  olympics::heartbeat_t h;
  h.protocol_version = kProtocolVersion;
  h.match_id = "srv-k1-1", h.client_id = "alice";
  return h;
}

// Handles messages on `t` for `ms`.
void pump(Transport& t, int ms) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
  while (std::chrono::steady_clock::now() < until) t.handle(5);
}

TEST(Freshness, ACapturedDatagramSentAgainIsDroppedWithoutAnAnswer) {
  const std::string url = lcm_url();
  auto secret = std::make_shared<const Authenticator>("a lab's deployment secret");
  Transport sender(TransportOptions(url, 0, 1, secret)),
      receiver(TransportOptions(url, 0, 1, secret)), attacker{TransportOptions(url)};
  int first = 0, second = 0;
  receiver.subscribe(kHeartbeat, [&](const std::string&, const std::uint8_t*, int) { ++first; });
  receiver.subscribe(kHeartbeat, [&](const std::string&, const std::uint8_t*, int) { ++second; });
  std::vector<std::uint8_t> captured;
  attacker.subscribe(kHeartbeat, [&](const std::string&, const std::uint8_t* d, int n) {
    captured.assign(d, d + n);
  });
  sender.publish(kHeartbeat, beat());
  for (int i = 0; i < 200 && captured.empty(); ++i) attacker.handle(10);
  ASSERT_FALSE(captured.empty());
  pump(receiver, 200);
  EXPECT_EQ(first, 1);
  EXPECT_EQ(second, 1) << "both subscriptions hear the original";
  for (int i = 0; i < 3; ++i)
    attacker.publish_raw(kHeartbeat, captured.data(), static_cast<int>(captured.size()));
  pump(receiver, 300);
  EXPECT_EQ(first, 1) << "the copies are not taken";
  EXPECT_EQ(second, 1);
  EXPECT_EQ(receiver.replayed(), 3);
  EXPECT_EQ(receiver.unauthenticated(), 0) << "a replay is signed: it is dropped as a replay";

  // A message signed long ago (the test holds the secret; an outsider cannot renew the time, it
  // is under the signature) is stale even for a receiver that never heard it.
  auto old = encode(beat());
  const int n = static_cast<int>(old.size());
  write_freshness(old.data() + n - kSignatureBytes,
                  {12345, 1, wall_clock_ms() - kMaxMessageAgeMs - 2000});
  secret->sign(kHeartbeat, old.data(), n);
  attacker.publish_raw(kHeartbeat, old.data(), n);
  auto renewed = old;  // the time changed without the key: the signature fails
  write_freshness(renewed.data() + n - kSignatureBytes, {12345, 1, wall_clock_ms()});
  attacker.publish_raw(kHeartbeat, renewed.data(), n);
  pump(receiver, 300);
  EXPECT_EQ(first, 1);
  EXPECT_EQ(receiver.stale(), 1);
  EXPECT_EQ(receiver.unauthenticated(), 1);
}

}  // namespace
}  // namespace olympics::protocol
