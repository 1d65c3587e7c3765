// A vector client against a real server process: matches that end are replaced without the
// server refusing the replacements.
#include "vector_client.h"

#include <atomic>
#include <thread>

#include "background_listener.h"
#include "channels.h"
#include "olympics/error_t.hpp"
#include "server_fixture.h"

namespace olympics::testing {
namespace {

// The FULL refusals the server sends.
class FullRefusals {
 public:
  explicit FullRefusals(const std::string& url) : listener_(url) {
    listener_.transport().subscribe_to<olympics::error_t>(
        protocol::kError, [this](const std::string&, const olympics::error_t& e) {
          if (e.code == "FULL") ++count;
        });
    listener_.listen();
  }
  std::atomic<long> count{0};

 private:
  BackgroundListener listener_;  // last: its thread stops before the count goes
};

// Every environment asks for its next match the moment its match's final observation comes,
// before the server has stored that match's result. A match stops counting against the
// capacity when it ends, so a client with exactly `capacity` environments is never refused
// (it used to get FULL at nearly every replacement, and waited 250 ms to ask again).
TEST(VectorClient, AsManyEnvironmentsAsTheServerHoldsReplaceEndedMatchesWithoutARefusal) {
  constexpr int kCapacity = 6;
  ServerFixture server({"--capacity", std::to_string(kCapacity), "--workers", "2"});
  FullRefusals refusals(server.url());
  client::ClientOptions options;
  options.lcm_url = server.url();
  client::VectorSettings settings;
  settings.num_envs = kCapacity;
  settings.request.sport = "sandbox";
  settings.request.mode = "1v1";
  settings.request.seed = 3;
  client::VectorClient client(options, settings);
  client.reset();
  const std::vector<float> zero(
      static_cast<size_t>(kCapacity * client.num_agents() * client.action_size()), 0.0f);
  int replaced = 0;
  while (replaced < 3 * kCapacity) {  // standing still, a sandbox humanoid falls in 2 s
    const auto& batch = client.step(zero);
    for (auto over : batch.episode_over) replaced += over;
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // any late refusal lands
  EXPECT_EQ(refusals.count.load(), 0) << "a replacement was refused although its match had ended";
}

}  // namespace
}  // namespace olympics::testing
