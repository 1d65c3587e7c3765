// The client's connection without a server: what it keeps for a match before a session takes
// it, and how long it waits before resending an action. LCM's in-process memq:// carries what
// the test publishes to the connection's own subscriptions.
#include "connection.h"

#include <gtest/gtest.h>

#include "channels.h"
#include "match_session.h"
#include "olympics/error_t.hpp"
#include "olympics/join_reply_t.hpp"
#include "version.h"

namespace olympics::client {
namespace {

ClientOptions in_process() {
  ClientOptions options;
  options.lcm_url = "memq://";
  return options;
}

olympics::match_created_t sandbox_match(const std::string& match_id) {
  olympics::match_created_t m{};
  m.protocol_version = protocol::kProtocolVersion;
  m.server_id = "srv";
  m.match_id = match_id;
  m.num_slots = 2;
  m.slot_team = {0, 1};
  m.obs_size = 3;
  m.action_size = 2;
  m.obs_channel = protocol::obs_channel(match_id);
  m.action_channel = protocol::action_channel(match_id);
  m.control_hz = 30;
  m.num_obs_blocks = 1;
  m.obs_block_names = {"all"};
  m.obs_block_sizes = {3};
  m.obs_block_field_counts = {2};
  m.num_obs_fields = 2;
  m.obs_field_names = {"height", "speed"};
  m.obs_field_sizes = {1, 2};
  return m;
}

olympics::observation_batch_t first_observation(const std::string& match_id,
                                                const std::string& client_id) {
  olympics::observation_batch_t b{};
  b.protocol_version = protocol::kProtocolVersion;
  b.match_id = match_id;
  b.client_id = client_id;
  b.tick = 0;
  b.num_slots = 1;
  b.slots = {0};
  b.obs_size = 3;
  b.obs = {{0.5f, 1.5f, 2.5f}};
  b.reward = {0.0f};
  b.num_terms = 0;
  b.terms = {{}};
  b.done = {0};
  b.truncated = {0};
  return b;
}

// The server sends a match's first observation right behind the join reply: it reaches the
// client before any session exists for the match, and used to be dropped (the match then
// waited for the server's resend, 30 ms or more, at every start).
TEST(Connection, KeepsAJoinedMatchsFirstObservationUntilItsSessionTakesIt) {
  Connection connection(in_process());
  connection.send_join("srv-1", {0});
  connection.transport().publish(protocol::obs_channel("srv-1"),
                                 first_observation("srv-1", connection.client_id()));
  connection.drain();
  MatchSession session(connection, sandbox_match("srv-1"), {0});
  auto o = session.take_observation();
  ASSERT_TRUE(o.has_value());
  EXPECT_EQ(o->tick, 0);
  EXPECT_EQ(o->obs.at(0), (std::vector<float>{0.5f, 1.5f, 2.5f}));
}

TEST(Connection, KeepsNothingForOtherClientsOrMatchesItDidNotJoin) {
  Connection connection(in_process());
  connection.send_join("srv-1", {0});
  connection.transport().publish(protocol::obs_channel("srv-1"),
                                 first_observation("srv-1", "someone-else"));
  connection.transport().publish(protocol::obs_channel("srv-2"),
                                 first_observation("srv-2", connection.client_id()));
  connection.drain();
  MatchSession joined(connection, sandbox_match("srv-1"), {0});
  MatchSession not_joined(connection, sandbox_match("srv-2"), {0});
  EXPECT_FALSE(joined.has_observation());
  EXPECT_FALSE(not_joined.has_observation());
}

TEST(Connection, ARefusedJoinStopsKeepingTheMatchsObservations) {
  Connection connection(in_process());
  connection.send_join("srv-1", {0});
  olympics::join_reply_t refused{};
  refused.protocol_version = protocol::kProtocolVersion;
  refused.match_id = "srv-1";
  refused.client_id = connection.client_id();
  refused.accepted = false;
  refused.reason = "slot 0 is taken";
  refused.match = sandbox_match("srv-1");
  connection.transport().publish(protocol::kJoinReply, refused);
  connection.drain();
  auto reply = connection.take_join_reply("srv-1");
  ASSERT_TRUE(reply.has_value());
  EXPECT_FALSE(reply->accepted);
  connection.transport().publish(protocol::obs_channel("srv-1"),
                                 first_observation("srv-1", connection.client_id()));
  connection.drain();
  MatchSession session(connection, sandbox_match("srv-1"), {0});
  EXPECT_FALSE(session.has_observation());
}

// Resends wait for twice the longest round trip of the last second: a client stepping many
// matches gets its answers spread over a step, and resending those still on their way only
// adds load.
TEST(Connection, ResendsWaitForTwiceTheLongestRecentRoundTripWithinBounds) {
  Connection connection(in_process());
  const double base = connection.options().resend_interval_s;
  EXPECT_DOUBLE_EQ(connection.resend_interval_s(), base) << "nothing measured yet";
  connection.note_round_trip(0.060);
  connection.note_round_trip(0.010);  // a shorter one does not lower it at once
  EXPECT_NEAR(connection.resend_interval_s(), 0.120, 0.002);
  connection.note_round_trip(0.001);
  EXPECT_GE(connection.resend_interval_s(), base);
  connection.note_round_trip(5.0);  // a stall, not a pace
  EXPECT_DOUBLE_EQ(connection.resend_interval_s(), 1.0);
}

olympics::error_t error(const std::string& match_id, const std::string& client_id,
                        const std::string& code, const std::string& message) {
  olympics::error_t e{};
  e.protocol_version = protocol::kProtocolVersion;
  e.server_id = "srv";
  e.match_id = match_id, e.client_id = client_id, e.code = code, e.message = message;
  return e;
}

// A client acts on an error only when it names what the client sent (issue 36, item 1): its
// pending request as the message's subject ("request <id>: "), not as any substring, and its
// own client id only with a match it joined.
TEST(Connection, ActsOnlyOnErrorsThatNameWhatItSent) {
  Connection connection(in_process());
  connection.send_request(Connection::request_message({}, "r1"));
  connection.send_join("srv-1", {0});
  auto& t = connection.transport();
  t.publish(protocol::kError, error("", "", "BAD_REQUEST", "request r12: another request"));
  t.publish(protocol::kError, error("", "", "FULL", "server x: request r1: not the subject"));
  t.publish(protocol::kError,
            error("srv-2", connection.client_id(), "UNKNOWN_MATCH", "a match never joined"));
  connection.drain();
  EXPECT_FALSE(connection.take_request_error("r1").has_value());
  EXPECT_FALSE(connection.fatal_error("srv-2").has_value());
  EXPECT_EQ(connection.ignored_errors(), 1);

  t.publish(protocol::kError, error("", "", "FULL", "request r1: server srv is full"));
  t.publish(protocol::kError,
            error("srv-1", connection.client_id(), "UNKNOWN_MATCH", "a match it joined"));
  connection.drain();
  auto refused = connection.take_request_error("r1");
  ASSERT_TRUE(refused.has_value());
  EXPECT_EQ(refused->code, "FULL");
  EXPECT_TRUE(connection.fatal_error("srv-1").has_value());
}

}  // namespace
}  // namespace olympics::client
