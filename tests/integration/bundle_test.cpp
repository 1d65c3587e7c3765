// A vector client's ticks travel in bundles: one datagram of actions per server and about one of
// observations per server worker, where each match used to take one of each. A bundle that does
// not add up is refused with a MALFORMED error, and the server plays on.
#include "bundle.h"

#include <atomic>
#include <thread>

#include "background_listener.h"
#include "channels.h"
#include "olympics/error_t.hpp"
#include "server_fixture.h"
#include "transport.h"
#include "vector_client.h"
#include "version.h"

namespace olympics::testing {
namespace {

// Counts the datagrams on each kind of channel, from its own thread, until destroyed.
class TrafficCounter {
 public:
  explicit TrafficCounter(const std::string& url) : listener_(url) {
    count(std::string(protocol::kObsPrefix) + ".*", match_observations);
    count(std::string(protocol::kActPrefix) + ".*", match_actions);
    count(std::string(protocol::kObsBundlePrefix) + ".*", observation_bundles);
    count(std::string(protocol::kActionBundlePrefix) + ".*", action_bundles);
    listener_.transport().subscribe_to<olympics::error_t>(
        protocol::kError, [this](const std::string&, const olympics::error_t& e) {
          if (e.code == "MALFORMED") ++malformed_errors;
        });
    listener_.listen();
  }
  std::atomic<long> match_observations{0}, match_actions{0}, observation_bundles{0},
      action_bundles{0}, malformed_errors{0};

 private:
  void count(const std::string& pattern, std::atomic<long>& counter) {
    listener_.transport().subscribe(
        pattern, [&counter](const std::string&, const std::uint8_t*, int) { ++counter; });
  }
  BackgroundListener listener_;  // last: its thread stops before the counters go
};

std::unique_ptr<client::VectorClient> sandbox_client(const std::string& url, int envs) {
  client::ClientOptions options;
  options.lcm_url = url;
  client::VectorSettings settings;
  settings.num_envs = envs;
  settings.request.sport = "sandbox";
  settings.request.mode = "1v1";
  settings.request.seed = 1;
  settings.request.time_limit_s = 30;  // no match ends within the test's ticks
  return std::make_unique<client::VectorClient>(options, settings);
}

TEST(Bundles, AVectorClientsTicksTravelInBundlesNotADatagramPerMatch) {
  ServerFixture server({"--workers", "1"});
  constexpr int kEnvs = 16, kSteps = 40;
  auto client = sandbox_client(server.url(), kEnvs);
  client->reset();
  TrafficCounter traffic(server.url());
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // its subscriptions are live
  const std::vector<float> actions(
      static_cast<size_t>(kEnvs * client->num_agents() * client->action_size()), 0.0f);
  for (int step = 0; step < kSteps; ++step) {
    auto batch = client->step(actions);
    ASSERT_EQ(batch.envs.size(), static_cast<size_t>(kEnvs));
    for (auto over : batch.episode_over) ASSERT_EQ(over, 0) << "a match ended early";
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the last datagrams land
  // One action bundle per step (16 sandbox action batches fit one datagram); resends after a
  // slow answer go on the matches' own channels.
  EXPECT_EQ(traffic.action_bundles.load(), kSteps);
  EXPECT_LT(traffic.match_actions.load(), kSteps * kEnvs / 4);
  // One worker answers a step's bundle in about one pass: a bundle or a few, never one datagram
  // per match (kSteps * kEnvs = 640 before bundles).
  EXPECT_GE(traffic.observation_bundles.load(), kSteps);
  EXPECT_LT(traffic.observation_bundles.load() + traffic.match_observations.load(),
            kSteps * kEnvs / 4)
      << traffic.observation_bundles.load() << " bundles, " << traffic.match_observations.load()
      << " observation batches alone";
}

TEST(Bundles, ABundleThatDoesNotAddUpIsRefusedAndPlayGoesOn) {
  ServerFixture server;
  auto client = sandbox_client(server.url(), 2);
  client->reset();
  TrafficCounter traffic(server.url());
  protocol::Transport attacker{protocol::TransportOptions(server.url())};
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const std::string channel = protocol::action_bundle_channel("srv");
  // Its sizes claim more bytes than it carries.
  olympics::bundle_t lying{};
  lying.protocol_version = protocol::kProtocolVersion;
  lying.client_id = "intruder";
  lying.num_parts = 1;
  lying.match_ids = {client->match(0).match_id};
  lying.part_sizes = {500};
  lying.num_bytes = 4;
  lying.parts = {1, 2, 3, 4};
  attacker.publish(channel, lying);
  // Not a bundle at all.
  const std::vector<std::uint8_t> junk(300, 0xAB);
  attacker.publish_raw(channel, junk.data(), static_cast<int>(junk.size()));
  // A well-formed bundle whose part is not an action batch of the match it names.
  protocol::BundleWriter writer("intruder");
  writer.add(client->match(1).match_id, std::vector<std::uint8_t>(64, 7));
  for (const auto& bundle : writer.take())
    attacker.publish_raw(channel, bundle.data(), static_cast<int>(bundle.size()));
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (traffic.malformed_errors.load() < 3 && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(traffic.malformed_errors.load(), 3) << "each bad bundle is answered with MALFORMED";
  const std::vector<float> actions(
      static_cast<size_t>(2 * client->num_agents() * client->action_size()), 0.0f);
  for (int step = 0; step < 10; ++step) {
    auto batch = client->step(actions);
    ASSERT_EQ(batch.envs.size(), 2u) << "both matches still play";
  }
}

}  // namespace
}  // namespace olympics::testing
