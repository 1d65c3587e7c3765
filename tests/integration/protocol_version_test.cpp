// A peer of another protocol version is told so: a request of the version before this one (a
// client built before match_created_t named the observation's fields) is answered UPGRADE, named
// by its request id so that the client reports it rather than waiting for an answer.
#include "channels.h"
#include "olympics/error_t.hpp"
#include "olympics/match_request_t.hpp"
#include "server_fixture.h"
#include "transport.h"
#include "version.h"

namespace olympics::testing {
namespace {

TEST(ProtocolVersion, AnOlderClientsRequestIsAnsweredUpgradeNamingTheRequest) {
  ServerFixture server;
  protocol::Transport transport{protocol::TransportOptions(server.url())};
  std::vector<olympics::error_t> errors;
  transport.subscribe(protocol::kError, [&](const std::string&, const std::uint8_t* d, int n) {
    if (auto e = protocol::decode<olympics::error_t>(d, n)) errors.push_back(*e);
  });
  olympics::match_request_t old;
  old.protocol_version = protocol::kProtocolVersion - 1;
  old.request_id = "from-the-past";
  old.sport = "sandbox";
  old.mode = "1v1";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (errors.empty() && std::chrono::steady_clock::now() < deadline) {
    transport.publish(protocol::kRequest, old);
    transport.handle(250);
  }
  ASSERT_FALSE(errors.empty()) << "no answer to an older client's request";
  const olympics::error_t& e = errors.front();
  EXPECT_EQ(e.code, "UPGRADE");
  EXPECT_EQ(e.message.rfind("request from-the-past: ", 0), 0u) << e.message;
  EXPECT_NE(e.message.find("upgrade the client to protocol " +
                           std::to_string(protocol::kProtocolVersion)),
            std::string::npos)
      << e.message;
}

}  // namespace
}  // namespace olympics::testing
