// The red team's second round (issue 36), over real LCM against a real signed server: an
// attacker without the secret records signed datagrams and sends them again, byte for byte.
// Signatures do not stop that; freshness does (protocol/freshness.h): every signed message
// carries its sender's boot, a sequence and the send time, and receivers take each once, and
// none sent more than kMaxMessageAgeMs ago. Each test failed before freshness was built.
#include <atomic>
#include <deque>
#include <map>
#include <mutex>
#include <thread>

#include "auth.h"
#include "channels.h"
#include "freshness.h"
#include "olympics/action_batch_t.hpp"
#include "server_fixture.h"
#include "transport.h"

namespace olympics::testing {
namespace {

using Clock = std::chrono::steady_clock;

std::string new_secret(const std::string& dir) {
  protocol::write_new_secret(dir + "/secret");
  return dir + "/secret";
}

// An attacker without the secret: records the datagrams on the channels it is given (LCM
// patterns) and sends them again, unchanged, when asked, or by itself `delay` after each was sent.
class Replayer {
 public:
  Replayer(const std::string& url, const std::vector<std::string>& channels,
           std::optional<Clock::duration> delay = std::nullopt)
      : transport_(protocol::TransportOptions(url)) {
    // Subscribed before its thread handles anything: LCM starts listening at the first
    // subscription, which must not race a handle().
    for (const auto& channel : channels)
      transport_.subscribe(channel,
                           [this, delay](const std::string& ch, const std::uint8_t* d, int n) {
                             std::lock_guard lock(mutex_);
                             if (!recording_) return;
                             captured_.push_back({ch, std::vector<std::uint8_t>(d, d + n)});
                             if (delay) due_.push_back({Clock::now() + *delay, captured_.back()});
                           });
    thread_ = std::thread([this] {
      while (running_) {
        transport_.handle(2);
        send_due();
      }
    });
  }
  ~Replayer() {
    running_ = false;
    thread_.join();
  }
  void stop_recording() {
    std::lock_guard lock(mutex_);
    recording_ = false;
  }
  struct Datagram {
    std::string channel;
    std::vector<std::uint8_t> bytes;
  };
  std::vector<Datagram> captured() {
    std::lock_guard lock(mutex_);
    return captured_;
  }
  // Sends every recorded datagram again, `times` times.
  long replay_all(int times = 1) {
    long bytes = 0;
    for (const auto& d : captured())
      for (int i = 0; i < times; ++i) bytes += send(d.channel, d.bytes);
    return bytes;
  }
  long send(const std::string& channel, const std::vector<std::uint8_t>& bytes) {
    transport_.publish_raw(channel, bytes.data(), static_cast<int>(bytes.size()));
    ++sent_;
    return static_cast<long>(bytes.size());
  }
  long sent() const { return sent_; }

 private:
  void send_due() {
    std::vector<Datagram> now;
    {
      std::lock_guard lock(mutex_);
      while (!due_.empty() && due_.front().first <= Clock::now()) {
        now.push_back(std::move(due_.front().second));
        due_.pop_front();
      }
    }
    for (const auto& d : now) send(d.channel, d.bytes);
  }
  protocol::Transport transport_;
  std::mutex mutex_;
  bool recording_ = true;
  std::vector<Datagram> captured_;
  std::deque<std::pair<Clock::time_point, Datagram>> due_;
  std::atomic<bool> running_{true};
  std::atomic<long> sent_{0};
  std::thread thread_;
};

std::vector<std::string> agent_args(const std::string& secret, const std::string& request,
                                    const std::string& slot, std::vector<std::string> extra = {}) {
  std::vector<std::string> a = {
      "--secret", secret,     "--request-id", request,         "--slots",
      slot,       "--policy", "random",       "--policy-seed", slot == "0" ? "1" : "2"};
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

// Both agents of one match; returns their exit codes' sum (0: both played to the end).
int play(ServerFixture& server, const std::string& secret, const std::string& request,
         const std::vector<std::string>& extra, std::string* output = nullptr) {
  auto a = server.agent(request + "-a", agent_args(secret, request, "0", extra));
  auto b = server.agent(request + "-b", agent_args(secret, request, "1", extra));
  const int ra = a->wait(120), rb = b->wait(120);
  if (output) *output = a->output() + "\n" + b->output();
  EXPECT_EQ(ra, 0) << a->output();
  EXPECT_EQ(rb, 0) << b->output();
  return std::abs(ra) + std::abs(rb);
}

std::string key(const std::vector<float>& action) {
  return {reinterpret_cast<const char*>(action.data()), action.size() * sizeof(float)};
}

TEST(ReplayAttack, ReplayedRealtimeActionsAreNeverApplied) {
  const std::string dir = temp_dir(), secret = new_secret(dir);
  ServerFixture server({"--secret", secret});
  // Each action again 10 ticks (1/3 s) late, as the red team did.
  Replayer attacker(server.url(), {std::string(protocol::kActPrefix) + ".*"},
                    std::chrono::milliseconds(333));
  std::string out;
  // Soccer: a match that lasts its time limit whatever the players do.
  ASSERT_EQ(play(server, secret, "rt",
                 {"--sport", "soccer", "--mode", "1v1", "--realtime", "--time-limit", "4"}, &out),
            0);
  attacker.stop_recording();
  // Which tick each action was sent for (a random policy: every action differs).
  std::map<std::pair<int, std::string>, int> sent_for;
  std::string match_id;
  for (const auto& d : attacker.captured())
    if (auto b = protocol::decode<olympics::action_batch_t>(d.bytes.data(),
                                                            static_cast<int>(d.bytes.size()))) {
      match_id = b->match_id;
      for (int i = 0; i < b->num_slots; ++i) sent_for[{b->slots[i], key(b->actions[i])}] = b->tick;
    }
  ASSERT_FALSE(match_id.empty());
  EXPECT_GT(attacker.sent(), 50) << "the attacker replayed the match's actions";
  // The actions the server applied, tick by tick: an action older than one already applied for
  // that slot means a replay was taken.
  const auto replay = server.replay(match_id);
  int applied_back_in_time = 0, ticks = replay.ticks();
  std::map<int, int> newest;
  for (int t = 0; t < ticks; ++t)
    for (int s = 0; s < replay.slot_count; ++s) {
      const float* a = &replay.actions[(t * replay.slot_count + s) * replay.action_size];
      auto it = sent_for.find({s, key(std::vector<float>(a, a + replay.action_size))});
      if (it == sent_for.end()) continue;  // no action yet (zeros)
      if (newest.count(s) && it->second < newest[s]) ++applied_back_in_time;
      newest[s] = std::max(newest[s], it->second);
    }
  EXPECT_GT(ticks, 60);
  EXPECT_EQ(applied_back_in_time, 0) << "of " << ticks << " ticks";
}

TEST(ReplayAttack, AnnouncementsOfAnEarlierBootEndNoMatch) {
  const std::string url = unique_lcm_url(), dir = temp_dir(), secret = new_secret(dir);
  Replayer attacker(url, {protocol::kAnnounce});
  {
    ServerFixture before({"--secret", secret}, url, "", "alpha");
    while (attacker.captured().size() < 2)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  attacker.stop_recording();
  ServerFixture alpha({"--secret", secret}, url, "", "alpha");
  std::atomic<bool> done{false};
  std::thread replaying([&] {
    while (!done) {
      attacker.replay_all();
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  });
  std::string out;
  const int failed = play(alpha, secret, "after",
                          {"--sport", "soccer", "--mode", "1v1", "--realtime", "--time-limit", "3",
                           "--server", "alpha"},
                          &out);
  done = true;
  replaying.join();
  EXPECT_EQ(failed, 0);
  EXPECT_EQ(out.find("SERVER_RESTARTED"), std::string::npos) << out;
  EXPECT_GT(attacker.sent(), 5);
}

TEST(ReplayAttack, AStoppedServersAnnouncementsDoNotSilenceTheLiveOne) {
  const std::string url = unique_lcm_url(), dir = temp_dir(), secret = new_secret(dir);
  Replayer attacker(url, {protocol::kAnnounce});
  ServerFixture bbb({"--secret", secret}, url, "", "bbb");
  {
    ServerFixture aaa({"--secret", secret}, url, "", "aaa");  // sorts first: takes requests
    while (attacker.captured().size() < 6)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    attacker.stop_recording();
  }
  std::atomic<bool> done{false};
  std::thread replaying([&] {
    while (!done) {
      attacker.replay_all();
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  });
  // Addressed to no server: the live one must take it, whatever aaa's copies say.
  std::string out;
  const int failed = play(bbb, secret, "unaddressed", {"--time-limit", "2"}, &out);
  done = true;
  replaying.join();
  EXPECT_EQ(failed, 0) << out;
  EXPECT_GT(attacker.sent(), 5);
}

TEST(ReplayAttack, OldRequestsReplayedToARestartedServerMakeNoMatch) {
  const std::string url = unique_lcm_url(), dir = temp_dir(), secret = new_secret(dir);
  Replayer attacker(url, {protocol::kRequest});
  {
    ServerFixture first({"--secret", secret, "--capacity", "1"}, url, "", "alpha");
    ASSERT_EQ(play(first, secret, "old", {"--time-limit", "1", "--server", "alpha"}), 0);
  }
  attacker.stop_recording();
  ASSERT_FALSE(attacker.captured().empty());
  // The server forgot the request (it restarted; a running one forgets after a while too): only
  // the time in the signature tells that the copies are old.
  std::this_thread::sleep_for(std::chrono::milliseconds(protocol::kMaxMessageAgeMs + 1000));
  ServerFixture again({"--secret", secret, "--capacity", "1"}, url, "", "alpha");
  attacker.replay_all(30);
  // A ghost match would hold the only place: the real players would be told FULL.
  std::string out;
  EXPECT_EQ(play(again, secret, "new", {"--time-limit", "1", "--server", "alpha"}, &out), 0);
  EXPECT_EQ(out.find("FULL"), std::string::npos) << out;
  again.server().signal(SIGTERM);
  again.server().wait(20);
  const std::string log = again.server().output();
  EXPECT_NE(log.find("stale"), std::string::npos) << "the copies were dropped and counted:\n"
                                                  << log;
}

// What the server sends on its own channels (errors, results, observations, descriptions; not
// its announcements, which go out every second whatever happens), in bytes.
class ReplyCounter {
 public:
  explicit ReplyCounter(const std::string& url) : transport_(protocol::TransportOptions(url)) {
    transport_.subscribe(".*", [this](const std::string& ch, const std::uint8_t*, int n) {
      if (ch == protocol::kAnnounce || protocol::sender_of(ch) != protocol::Role::Server) return;
      bytes_ += n;
      std::lock_guard lock(mutex_);
      by_channel_[ch.substr(0, 8)] += n;
    });
    thread_ = std::thread([this] {
      while (running_) transport_.handle(5);
    });
  }
  ~ReplyCounter() {
    running_ = false;
    thread_.join();
  }
  long bytes() const { return bytes_; }
  std::string breakdown() {
    std::string s;
    std::lock_guard lock(mutex_);
    for (auto& [ch, n] : by_channel_) s += ch + ": " + std::to_string(n) + " ";
    return s;
  }

 private:
  protocol::Transport transport_;
  std::atomic<long> bytes_{0};
  std::mutex mutex_;
  std::map<std::string, long> by_channel_;
  std::atomic<bool> running_{true};
  std::thread thread_;
};

TEST(ReplayAttack, NoAnswerToUnauthenticatedOrReplayedInputIsBiggerThanIt) {
  const std::string dir = temp_dir(), secret = new_secret(dir);
  ServerFixture server({"--secret", secret}, unique_lcm_url(), "", "alpha");
  Replayer attacker(server.url(), {protocol::kRequest, protocol::kJoin, protocol::kHeartbeat,
                                   std::string(protocol::kActPrefix) + ".*"});
  ASSERT_EQ(play(server, secret, "done", {"--time-limit", "1", "--server", "alpha"}), 0);
  attacker.stop_recording();
  const auto captured = attacker.captured();
  std::map<std::string, int> kinds;
  for (const auto& d : captured) ++kinds[d.channel.substr(0, 8)];
  for (const auto& [k, n] : kinds) std::printf("captured %s: %d\n", k.c_str(), n);
  ASSERT_GT(captured.size(), 20u);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // the match's last words

  ReplyCounter replies(server.url());
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  long in = 0;
  // 1. The finished match's signed datagrams, again (it would answer each with its result).
  in += attacker.replay_all(3);
  // 2. The same, unsigned (the signature zeroed), and cut short.
  for (const auto& d : captured) {
    auto copy = d.bytes;
    std::fill(copy.end() - protocol::kSignatureBytes, copy.end(), std::uint8_t{0});
    in += attacker.send(d.channel, copy);
    copy.resize(copy.size() / 2);
    in += attacker.send(d.channel, copy);
  }
  // 3. Small garbage on every channel a server listens to.
  for (int size = 1; size <= 120; size += 7)
    for (const std::string& ch : std::vector<std::string>{
             protocol::kRequest, protocol::kJoin, protocol::kHeartbeat,
             protocol::action_channel("alpha-x-1"), protocol::action_bundle_channel("alpha")})
      in += attacker.send(ch, std::vector<std::uint8_t>(size, 0x5a));
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  const long out = replies.bytes();
  EXPECT_LE(out, in) << "bytes out " << out << " for bytes in " << in << ": "
                     << replies.breakdown();
  std::printf("amplification: %ld bytes out for %ld bytes in (%s)\n", out, in,
              replies.breakdown().c_str());
}

}  // namespace
}  // namespace olympics::testing
