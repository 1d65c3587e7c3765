// Fuzzing live processes: a server, two agents in a match and a league running a tournament, on
// a deployment with a secret. A fuzzer records their traffic on every channel they listen on,
// then sends 15,000 mutated copies (tests/fuzz/mutator.h: bit flips, hostile lengths and
// counts, poisoned floats, truncation, garbage), half of them re-signed with
// the secret so that they get past the signature check to the decoders and handlers. Afterwards
// no process has died of a signal, the league finishes, and a normal match completes and is
// stored.
#include <algorithm>
#include <csignal>
#include <map>
#include <thread>

#include "auth.h"
#include "bundle.h"
#include "channels.h"
#include "freshness.h"
#include "league_store.h"
#include "mutator.h"
#include "olympics/error_t.hpp"
#include "olympics/league_assignment_t.hpp"
#include "olympics/server_announce_t.hpp"
#include "server_fixture.h"
#include "transport.h"
#include "version.h"

namespace olympics::testing {
namespace {

using Clock = std::chrono::steady_clock;

// The message type of a channel.
std::string type_of(const std::string& channel) {
  static const std::map<std::string, std::string> fixed = {
      {protocol::kAnnounce, "server_announce_t"}, {protocol::kRequest, "match_request_t"},
      {protocol::kCreated, "match_created_t"},    {protocol::kJoin, "join_t"},
      {protocol::kJoinReply, "join_reply_t"},     {protocol::kStart, "match_start_t"},
      {protocol::kResult, "match_result_t"},      {protocol::kError, "error_t"},
      {protocol::kHeartbeat, "heartbeat_t"},      {protocol::kLeague, "league_assignment_t"}};
  if (auto it = fixed.find(channel); it != fixed.end()) return it->second;
  if (channel.rfind(protocol::kActionBundlePrefix, 0) == 0 ||
      channel.rfind(protocol::kObsBundlePrefix, 0) == 0)
    return "bundle_t";
  if (channel.rfind(protocol::kObsPrefix, 0) == 0) return "observation_batch_t";
  if (channel.rfind(protocol::kActPrefix, 0) == 0) return "action_batch_t";
  return "";
}

TEST(Fuzz, ThousandsOfMutatedMessagesOnEveryChannelCrashNothing) {
  const std::string dir = temp_dir(), secret = dir + "/secret";
  protocol::write_new_secret(secret);
  const std::string url = unique_lcm_url();
  // Mutated requests create matches: room for them, and they give up soon. Hostile clients that
  // join and go quiet forfeit at the usual deadlines.
  ServerFixture server({"--secret", secret, "--capacity", "5000", "--join-timeout-s", "2",
                        "--action-deadline-ms", "1000", "--max-missed-ticks", "5"},
                       url, "", "srv");
  auto agent = [&](const std::string& name, std::vector<std::string> args) {
    std::vector<std::string> argv = {program("olympics-agent"),
                                     "--lcm-url",
                                     url,
                                     "--secret",
                                     secret,
                                     "--name",
                                     name,
                                     "--json",
                                     "--timeout",
                                     "60"};
    argv.insert(argv.end(), args.begin(), args.end());
    return std::make_unique<Process>(argv, dir + "/" + name + ".log");
  };
  auto a = agent("slow-a", {"--request-id", "long", "--slots", "0", "--policy", "random",
                            "--think-ms", "20", "--time-limit", "120"});
  auto b = agent("slow-b", {"--request-id", "long", "--slots", "1", "--policy", "random",
                            "--think-ms", "20", "--time-limit", "120"});
  ASSERT_TRUE(a->wait_for_output("joined", 30)) << a->output();
  Process league({program("olympics-league"), "run", "--db", dir + "/league.db", "--name", "cup",
                  "--entrants", "zero,random:1,random:2", "--time-limit", "2", "--lcm-url", url,
                  "--secret", secret, "--log-dir", dir, "--quiet"},
                 dir + "/league.log");

  // Record what flows, on every channel.
  protocol::Transport listener{protocol::TransportOptions(url)};
  std::map<std::string, std::vector<std::vector<std::uint8_t>>> seen;
  listener.subscribe(".*", [&](const std::string& ch, const std::uint8_t* d, int n) {
    if (type_of(ch).empty()) return;
    auto& list = seen[ch];
    if (list.size() < 30) list.emplace_back(d, d + n);
  });
  // Until every kind of message has been seen (a league game has ended), and for 2 s at least.
  const char* needed[] = {protocol::kRequest,   protocol::kJoin,   protocol::kCreated,
                          protocol::kJoinReply, protocol::kResult, protocol::kAnnounce,
                          protocol::kHeartbeat};
  auto all_seen = [&] {
    return std::all_of(std::begin(needed), std::end(needed),
                       [&](const char* ch) { return seen.count(ch) > 0; });
  };
  const auto at_least = Clock::now() + std::chrono::seconds(2);
  for (auto give_up = Clock::now() + std::chrono::seconds(120);
       Clock::now() < give_up && (Clock::now() < at_least || !all_seen());)
    listener.handle(10);
  // Channels nobody happened to use yet get a message of their own.
  olympics::error_t error;
  error.protocol_version = protocol::kProtocolVersion;
  error.server_id = "srv", error.client_id = "x", error.code = "BAD_ACTION", error.message = "m";
  seen[protocol::kError].push_back(protocol::encode(error));
  olympics::league_assignment_t assignment;
  assignment.protocol_version = protocol::kProtocolVersion;
  assignment.learner = "x", assignment.match_id = "srv-1", assignment.num_slots = 1;
  assignment.slots = {0};
  seen[protocol::kLeague].push_back(protocol::encode(assignment));
  // The agents send no bundles: one of a recorded action batch, to the server's bundle channel.
  std::vector<std::vector<std::uint8_t>> bundles;
  for (const auto& [ch, list] : seen)
    if (ch.rfind(protocol::kActPrefix, 0) == 0 && bundles.empty()) {
      protocol::BundleWriter writer("x");
      writer.add(ch.substr(std::string(protocol::kActPrefix).size()), list.front());
      bundles = writer.take();
    }
  EXPECT_FALSE(bundles.empty()) << "no action batch was seen to bundle";
  if (!bundles.empty()) seen[protocol::action_bundle_channel("srv")] = bundles;
  std::vector<std::string> channels;
  for (const auto& [ch, list] : seen) channels.push_back(ch);
  std::printf("fuzzing %zu channels\n", channels.size());
  for (const char* ch : needed)
    EXPECT_TRUE(seen.count(ch)) << ch << " was not seen: the fuzz would miss it";

  const auto auth = protocol::Authenticator::from_file(secret);
  fuzz::Mutator mutate(2026);
  // A fixed number, paced (50 every 20 ms) so that the receivers' buffers keep up.
  constexpr long kMutations = 15000;
  long sent = 0;
  while (sent < kMutations) {
    const std::string& ch = channels[mutate.pick(static_cast<int>(channels.size()))];
    const auto& pool = seen[ch];
    auto bytes = mutate.mutate(type_of(ch), pool[mutate.pick(static_cast<int>(pool.size()))]);
    if (mutate.pick(2) && bytes.size() >= protocol::kSignatureBytes + 8) {
      // Signed mutants reach the decoders only when fresh (protocol/freshness.h): most get a
      // freshness of their own, the rest keep what the mutation made of the recorded one
      // (replays, garbage times: the windows' checks are fuzzed too).
      if (mutate.pick(4))
        protocol::write_freshness(
            bytes.data() + bytes.size() - protocol::kSignatureBytes,
            {0xf022, static_cast<std::uint64_t>(sent + 1), protocol::wall_clock_ms()});
      auth.sign(ch, bytes.data(), static_cast<int>(bytes.size()));
    }
    listener.publish_raw(ch, bytes.data(), static_cast<int>(bytes.size()));
    if (++sent % 50 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::printf("sent %ld mutated messages\n", sent);

  // The mutations reached both the signature check and the decoders: the server says so. Our own
  // mutated announcements are still queued here; drain them before listening for the real one.
  for (auto until = Clock::now() + std::chrono::seconds(1); Clock::now() < until;)
    listener.handle(10);
  std::optional<olympics::server_announce_t> announced;
  listener.subscribe_to<olympics::server_announce_t>(
      protocol::kAnnounce, [&](const std::string&, const olympics::server_announce_t& m) {
        if (m.server_id == "srv") announced = m;
      });
  for (auto until = Clock::now() + std::chrono::seconds(10); Clock::now() < until && !announced;)
    listener.handle(10);
  ASSERT_TRUE(announced);
  std::printf("the server refused %ld malformed and %ld unauthenticated messages\n",
              static_cast<long>(announced->refused_malformed),
              static_cast<long>(announced->refused_unauthenticated));
  EXPECT_GT(announced->refused_malformed, 100);
  EXPECT_GT(announced->refused_unauthenticated, 100);

  // Nobody died of a signal; the slow match's agents may have been told off by signed garbage
  // (an insider's), but exit cleanly if they exit.
  EXPECT_TRUE(server.server().running()) << server.server().output();
  for (auto* p : {a.get(), b.get()}) {
    const int code = p->running() ? 0 : p->wait(1);
    EXPECT_LT(code, 128) << "an agent died of signal " << code - 128 << "\n" << p->output();
  }
  const int league_code = league.wait(120);
  EXPECT_TRUE(league_code == 0 || league_code == 2) << league_code << "\n" << league.output();
  // And a normal match still plays to a stored end.
  auto x = agent("after-x", {"--request-id", "after", "--slots", "0", "--time-limit", "1"});
  auto y = agent("after-y", {"--request-id", "after", "--slots", "1", "--time-limit", "1"});
  ASSERT_EQ(x->wait(60), 0) << x->output();
  ASSERT_EQ(y->wait(60), 0) << y->output();
  const auto r = ServerFixture::agent_result(*x);
  EXPECT_TRUE(server.store()->find(r.at("match_id")).has_value());
  EXPECT_TRUE(server.server().running());
}

}  // namespace
}  // namespace olympics::testing
