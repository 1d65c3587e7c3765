#include "transport.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "channels.h"

namespace olympics::protocol {
namespace {
constexpr int kQueueCapacity = 100000;

std::uint64_t random_boot() {
  std::random_device rd;
  std::uint64_t boot = 0;
  while (boot == 0) boot = (static_cast<std::uint64_t>(rd()) << 32) ^ rd();
  return boot;
}
}  // namespace

struct Transport::Subscription {
  Transport* transport = nullptr;
  RawHandler handler;
  lcm::Subscription* lcm_subscription = nullptr;
  void on_message(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
    const auto* data = static_cast<const std::uint8_t*>(rbuf->data);
    const int size = static_cast<int>(rbuf->data_size);
    // LCM hands one datagram to every subscription its channel matches, within one handle():
    // it is checked (and counted) once.
    auto& verdict = transport->dispatch_verdict_;
    if (!verdict) verdict = transport->admit(channel, data, size);
    if (*verdict) handler(channel, data, size);
  }
};

bool Transport::admit(const std::string& channel, const std::uint8_t* data, int size) {
  if (!auth_) return true;
  if (!auth_->verify(channel, data, size)) {
    ++unauthenticated_;
    if (on_unauthenticated_) on_unauthenticated_(channel, data, size);
    return false;
  }
  return fresh(data, size);  // no answer to a replay
}

Transport::Transport(const TransportOptions& options)
    : url_(options.url.empty() ? kDefaultLcmUrl : options.url),
      lcm_(url_),
      drop_rate_(options.drop_rate),
      drop_rng_(options.drop_seed),
      auth_(options.auth),
      boot_(random_boot()) {
  if (!(drop_rate_ >= 0 && drop_rate_ < 1))  // NaN too: it would drop nothing, silently
    throw std::invalid_argument("the test drop rate (--drop-rate) must be in [0, 1), got " +
                                std::to_string(drop_rate_));
  if (!lcm_.good())
    throw std::runtime_error(
        "LCM could not start on " + url_ +
        ". For udpm:// on one machine the loopback interface needs a multicast route: "
        "`sudo ip link set lo multicast on && sudo ip route add 224.0.0.0/4 dev lo`; "
        "or pass another --lcm-url.");
}

Transport::~Transport() = default;

int Transport::subscribe(const std::string& channel, RawHandler handler) {
  auto sub = std::make_unique<Subscription>();
  sub->transport = this;
  sub->handler = std::move(handler);
  sub->lcm_subscription = lcm_.subscribe(channel, &Subscription::on_message, sub.get());
  // LCM drops messages beyond 30 queued per subscription by default; a server with many matches
  // (or a player of a log) receives bursts far larger than that.
  sub->lcm_subscription->setQueueCapacity(kQueueCapacity);
  subscriptions_.push_back(std::move(sub));
  return static_cast<int>(subscriptions_.size()) - 1;
}

void Transport::unsubscribe(int handle) {
  auto& sub = subscriptions_.at(handle);
  if (!sub) return;
  lcm_.unsubscribe(sub->lcm_subscription);
  sub.reset();
}

void Transport::publish_raw(const std::string& channel, const std::uint8_t* data, int size) {
  send(channel, data, size, /*sign=*/true);
}

void Transport::send(const std::string& channel, const std::uint8_t* data, int size, bool sign) {
  std::lock_guard lock(publish_mutex_);
  ++published_;
  if (drop_rate_ > 0 && std::uniform_real_distribution<double>(0, 1)(drop_rng_) < drop_rate_) {
    ++dropped_;
    return;
  }
  if (auth_ && sign && size >= kSignatureBytes) {
    signing_buffer_.assign(data, data + size);
    write_freshness(signing_buffer_.data() + size - kSignatureBytes,
                    {boot_, next_seq_++, wall_clock_ms()});
    auth_->sign(channel, signing_buffer_.data(), size);
    data = signing_buffer_.data();
  }
  lcm_.publish(channel, data, static_cast<unsigned>(size));
}

int multicast_ttl(const std::string& url) {
  const auto query = url.find('?');
  if (query == std::string::npos) return 0;
  for (size_t at = query + 1; at < url.size();) {
    const size_t end = std::min(url.find('&', at), url.size());
    if (url.compare(at, 4, "ttl=") == 0) {
      try {
        return std::stoi(url.substr(at + 4, end - at - 4));
      } catch (const std::exception&) {
        return 1;  // unreadable: assume it leaves the host
      }
    }
    at = end + 1;
  }
  return 0;
}

bool Transport::fresh(const std::uint8_t* data, int size) {
  const Freshness f = read_freshness(data + size - kSignatureBytes);  // verified: size fits
  switch (windows_.admit(f, wall_clock_ms())) {
    case ReplayWindows::Verdict::Fresh:
      return true;
    case ReplayWindows::Verdict::Replayed:
      ++replayed_;
      if (const long n = replay_log_.note())
        std::fprintf(
            stderr, "[transport] dropped %ld replayed message(s) (taken here before; %ld in all)\n",
            n, replayed_.load());
      return false;
    case ReplayWindows::Verdict::Stale:
      ++stale_;
      if (const long n = stale_log_.note())
        std::fprintf(stderr,
                     "[transport] dropped %ld message(s) sent more than %lld s ago or ahead by "
                     "their sender's clock (%ld in all): replays, or hosts whose clocks are apart "
                     "(keep them in step, e.g. NTP)\n",
                     n, static_cast<long long>(kMaxMessageAgeMs / 1000), stale_.load());
      return false;
  }
  return false;
}

bool Transport::handle(int timeout_ms) {
  dispatch_verdict_.reset();
  return lcm_.handleTimeout(timeout_ms) > 0;
}

}  // namespace olympics::protocol
