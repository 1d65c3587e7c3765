// A vector client against a real server process: matches that end are replaced without the
// server refusing the replacements.
#include "vector_client.h"

#include <atomic>
#include <thread>

#include "channels.h"
#include "olympics/error_t.hpp"
#include "server_fixture.h"
#include "transport.h"

namespace olympics::testing {
namespace {

// The errors the server sends, by code, heard from a thread of its own until destroyed.
class ErrorListener {
 public:
  explicit ErrorListener(const std::string& url) : transport_(protocol::TransportOptions(url)) {
    transport_.subscribe_to<olympics::error_t>(
        protocol::kError, [this](const std::string&, const olympics::error_t& e) {
          if (e.code == "FULL") ++full;
        });
    thread_ = std::thread([this] {
      while (!stop_) transport_.handle(20);
    });
  }
  ~ErrorListener() {
    stop_ = true;
    thread_.join();
  }
  std::atomic<long> full{0};

 private:
  protocol::Transport transport_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// Every environment asks for its next match the moment its match's final observation comes,
// before the server has stored that match's result. A match stops counting against the
// capacity when it ends, so a client with exactly `capacity` environments is never refused
// (it used to get FULL at nearly every replacement, and waited 250 ms to ask again).
TEST(VectorClient, AsManyEnvironmentsAsTheServerHoldsReplaceEndedMatchesWithoutARefusal) {
  constexpr int kCapacity = 6;
  ServerFixture server({"--capacity", std::to_string(kCapacity), "--workers", "2"});
  ErrorListener errors(server.url());
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
  EXPECT_EQ(errors.full.load(), 0) << "a replacement was refused although its match had ended";
}

}  // namespace
}  // namespace olympics::testing
