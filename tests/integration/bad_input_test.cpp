// Bad input gets a clear error on OLY_ERROR and disturbs nothing: the match it was aimed at
// still plays to its end and is stored.
#include <cmath>
#include <fstream>

#include "auth.h"
#include "channels.h"
#include "match_client.h"
#include "olympics/action_batch_t.hpp"
#include "olympics/error_t.hpp"
#include "olympics/join_t.hpp"
#include "server_fixture.h"
#include "version.h"

namespace olympics::testing {
namespace {

// Listens to OLY_ERROR and sends hand-made (bad) messages.
class Prankster {
 public:
  explicit Prankster(const std::string& url) : transport_(protocol::TransportOptions(url)) {
    transport_.subscribe(protocol::kError,
                         [this](const std::string&, const std::uint8_t* d, int n) {
                           if (auto e = protocol::decode<olympics::error_t>(d, n))
                             errors_.push_back(*e);
                         });
  }
  // Waits for an error with this code (up to 30 s); returns its message ("" if none came).
  std::string expect_error(const std::string& code, double wait_s = 30) {
    auto deadline = std::chrono::steady_clock::now() +
                    std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                        std::chrono::duration<double>(wait_s));
    while (std::chrono::steady_clock::now() < deadline) {
      for (auto it = errors_.begin(); it != errors_.end(); ++it)
        if (it->code == code) {
          std::string m = it->message;
          errors_.erase(it);
          return m;
        }
      transport_.handle(20);
    }
    return "";
  }
  protocol::Transport& transport() { return transport_; }

 private:
  protocol::Transport transport_;
  std::vector<olympics::error_t> errors_;
};

olympics::action_batch_t action(const client::MatchClient& c, int tick, std::vector<int> slots,
                                int size) {
  olympics::action_batch_t b;
  b.protocol_version = protocol::kProtocolVersion;
  b.match_id = c.match().match_id;
  b.client_id = c.client_id();
  b.tick = tick;
  b.num_slots = static_cast<int>(slots.size());
  b.slots = slots;
  b.action_size = size;
  b.actions.assign(slots.size(), std::vector<float>(size, 0.0f));
  return b;
}

TEST(BadInput, EveryBadMessageGetsAClearErrorAndTheMatchPlaysOn) {
  ServerFixture server;
  Prankster prank(server.url());
  client::ClientOptions oa, ob;
  oa.lcm_url = ob.lcm_url = server.url();
  oa.agent_name = "a", ob.agent_name = "b";
  client::MatchClient a(oa), b(ob);
  client::MatchRequest req;
  req.request_id = "bad";
  req.time_limit_s = 3;
  auto created = a.request_match(req);
  a.join(created.match_id, {0});
  b.join(created.match_id, {1});
  const std::string act = created.action_channel;
  const int size = created.action_size;

  // A second client claiming a taken slot is refused and told why.
  client::ClientOptions oc = oa;
  oc.agent_name = "intruder";
  client::MatchClient intruder(oc);
  try {
    intruder.join(created.match_id, {1}, 5);
    ADD_FAILURE() << "the taken slot was given away";
  } catch (const client::MatchError& e) {
    EXPECT_EQ(e.code(), "SLOT_TAKEN");
    EXPECT_NE(std::string(e.what()).find("already taken by agent \"b\""), std::string::npos)
        << e.what();
  }

  auto oa0 = a.next(), ob0 = b.next();
  ASSERT_TRUE(oa0 && ob0);
  ASSERT_EQ(oa0->tick, 0);

  auto nan = action(a, 0, {0}, size);
  nan.actions[0][5] = std::nanf("");
  prank.transport().publish(act, nan);
  EXPECT_NE(prank.expect_error("BAD_ACTION").find("action[5] is NaN or Inf"), std::string::npos);

  auto inf = action(a, 0, {0}, size);
  inf.actions[0][0] = INFINITY;
  prank.transport().publish(act, inf);
  EXPECT_NE(prank.expect_error("BAD_ACTION"), "");

  prank.transport().publish(act, action(a, 0, {0}, size - 1));
  EXPECT_NE(prank.expect_error("BAD_ACTION").find("this match takes 69 floats"), std::string::npos);

  prank.transport().publish(act, action(a, 0, {1}, size));  // b's slot
  EXPECT_NE(prank.expect_error("UNKNOWN_SLOT").find("slot 1 is not yours"), std::string::npos);
  prank.transport().publish(act, action(a, 0, {7}, size));
  EXPECT_NE(prank.expect_error("UNKNOWN_SLOT").find("slot 7 does not exist"), std::string::npos);

  // An empty batch counted as the client's action for the tick, and a slot named twice in one
  // batch took the last of its actions silently (issue 36, item 9).
  prank.transport().publish(act, action(a, 0, {}, size));
  EXPECT_NE(prank.expect_error("BAD_ACTION").find("names no slot"), std::string::npos);
  prank.transport().publish(act, action(a, 0, {0, 0}, size));
  EXPECT_NE(prank.expect_error("BAD_ACTION").find("slot 0 appears twice"), std::string::npos);

  prank.transport().publish(act, action(a, 5, {0}, size));
  EXPECT_NE(prank.expect_error("FUTURE_TICK").find("the match is at tick 0"), std::string::npos);

  auto old = action(a, 0, {0}, size);
  old.protocol_version = 99;
  prank.transport().publish(act, old);
  EXPECT_NE(prank.expect_error("UPGRADE").find("upgrade the server"), std::string::npos);

  prank.transport().publish(protocol::action_channel("srv-999"), action(a, 0, {0}, size));
  EXPECT_NE(prank.expect_error("UNKNOWN_MATCH").find("no match \"srv-999\""), std::string::npos);

  // Truncated and garbage packets.
  auto good = action(a, 0, {0}, size);
  std::vector<std::uint8_t> bytes(good.getEncodedSize());
  good.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  prank.transport().publish_raw(act, bytes.data(), static_cast<int>(bytes.size()) / 2);
  EXPECT_NE(prank.expect_error("MALFORMED").find("could not decode a action_batch_t"),
            std::string::npos);
  // Garbage: answered with MALFORMED when the answer is no bigger than the garbage (issue 36:
  // nothing answers bad input with more bytes than it got), with nothing when it would be.
  const std::vector<std::uint8_t> garbage(400, 0x5a), tiny = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  prank.transport().publish_raw(protocol::kJoin, garbage.data(), 400);
  EXPECT_NE(prank.expect_error("MALFORMED").find("join_t"), std::string::npos);
  prank.transport().publish_raw(protocol::kRequest, garbage.data(), 400);
  EXPECT_NE(prank.expect_error("MALFORMED").find("match_request_t"), std::string::npos);
  prank.transport().publish_raw(protocol::kRequest, tiny.data(), 9);
  EXPECT_EQ(prank.expect_error("MALFORMED", 1.0), "") << "an answer bigger than the question";

  // None of it moved the match: still tick 0, and it plays on to a stored end.
  std::vector<std::vector<float>> zero(1, std::vector<float>(size, 0.0f));
  a.act(0, zero);
  b.act(0, zero);
  auto oa1 = a.next();
  ASSERT_TRUE(oa1);
  EXPECT_EQ(oa1->tick, 1);
  b.next();
  prank.transport().publish(act, action(a, 0, {0}, size));  // a resend of tick 0: ignored quietly
  a.act(1, zero);
  b.act(1, zero);
  a.next(), b.next();
  a.act(2, zero), b.act(2, zero);
  a.next(), b.next();
  prank.transport().publish(act, action(a, 0, {0}, size));  // two ticks old: stale
  EXPECT_NE(prank.expect_error("STALE_TICK").find("action for tick 0 arrived at tick 3"),
            std::string::npos);
  for (int tick = 3;; ++tick) {
    a.act(tick, zero), b.act(tick, zero);
    auto x = a.next();
    auto y = b.next();
    if (!x || x->all_done()) break;
  }
  const auto& result = a.wait_result();
  EXPECT_GT(result.ticks, 3);
  EXPECT_TRUE(server.store()->find(created.match_id).has_value());
}

TEST(BadInput, UnknownSportListsTheKnownOnes) {
  ServerFixture server;
  client::ClientOptions o;
  o.lcm_url = server.url();
  client::MatchClient c(o);
  client::MatchRequest req;
  req.sport = "quidditch";
  try {
    c.request_match(req, 5);
    ADD_FAILURE() << "an unknown sport was accepted";
  } catch (const client::MatchError& e) {
    EXPECT_EQ(e.code(), "UNKNOWN_SPORT");
    EXPECT_NE(std::string(e.what()).find("unknown sport \"quidditch\"; known sports: sandbox"),
              std::string::npos)
        << e.what();
  }
  req.sport = "sandbox";
  req.mode = "9v9";
  try {
    c.request_match(req, 5);
    ADD_FAILURE() << "an unknown mode was accepted";
  } catch (const client::MatchError& e) {
    EXPECT_EQ(e.code(), "BAD_REQUEST");
    EXPECT_NE(std::string(e.what()).find("modes: solo, 1v1, 2v2"), std::string::npos) << e.what();
  }
}

TEST(BadInput, BadConfigFileNamesFileLineAndProblem) {
  std::string dir = temp_dir();
  auto run_with = [&](const std::string& text) {
    std::ofstream(dir + "/bad.toml") << text;
    Process p({program("olympics-server"), "serve", "--config", dir + "/bad.toml"},
              dir + "/out.log");
    EXPECT_EQ(p.wait(10), 2);
    return p.output();
  };
  std::string out = run_with("[server]\ncapacity = 4\ncapacty = 5\n");
  EXPECT_NE(out.find("bad.toml:3:11: unknown key \"capacty\" in [server]"), std::string::npos)
      << out;
  out = run_with("[server]\ncapacity = \"many\"\n");
  EXPECT_NE(out.find("bad.toml:2:12: [server] capacity has the wrong type"), std::string::npos)
      << out;
  out = run_with("[server\n");
  EXPECT_NE(out.find("bad.toml:1:"), std::string::npos) << out;
  out = run_with("[sevrer]\nid = \"x\"\n");
  EXPECT_NE(out.find("unknown section \"sevrer\""), std::string::npos) << out;
  Process missing({program("olympics-server"), "serve", "--config", dir + "/none.toml"},
                  dir + "/m.log");
  EXPECT_EQ(missing.wait(10), 2);
  EXPECT_NE(missing.output().find("none.toml: cannot open the config file"), std::string::npos)
      << missing.output();
}

// Match ids are "<server id>-<boot>-<n>": a server "a" claimed every match of a server "a-b"
// (issue 36, item 6), and an id is also part of a channel LCM reads as a regular expression.
TEST(BadInput, AServerIdOtherThanLettersDigitsAndUnderscoreIsRefused) {
  std::string dir = temp_dir();
  for (std::string id : {"a-b", "s.*", "two words", "x/y"}) {
    Process p(
        {program("olympics-server"), "serve", "--id", id, "--results", dir + "/r.db", "--dry-run"},
        dir + "/out.log");
    EXPECT_EQ(p.wait(10), 2) << id << ": " << p.output();
    EXPECT_NE(p.output().find("a letter (A-Z, a-z), a digit or '_'"), std::string::npos)
        << p.output();
    EXPECT_NE(p.output().find("got \"" + id + "\""), std::string::npos) << p.output();
  }
  Process fine({program("olympics-server"), "serve", "--id", "Lab_2", "--results", dir + "/r.db",
                "--dry-run"},
               dir + "/fine.log");
  EXPECT_EQ(fine.wait(10), 0) << fine.output();
  Process default_id({program("olympics-server"), "serve", "--results", dir + "/r.db", "--dry-run"},
                     dir + "/default.log");
  EXPECT_EQ(default_id.wait(10), 0) << "the default id (host_pid) is valid\n"
                                    << default_id.output();
}

TEST(BadInput, ANanDropRateIsRefusedByServerAndAgent) {
  std::string dir = temp_dir();
  Process p({program("olympics-server"), "serve", "--drop-rate", "nan", "--results", dir + "/r.db",
             "--dry-run"},
            dir + "/out.log");
  EXPECT_EQ(p.wait(10), 2) << p.output();
  EXPECT_NE(p.output().find("--drop-rate) must be in [0, 1), got"), std::string::npos)
      << p.output();
  EXPECT_NE(p.output().find("nan"), std::string::npos) << p.output();
  Process agent({program("olympics-agent"), "--drop-rate", "nan", "--match", "srv-x-1"},
                dir + "/agent.log");
  EXPECT_EQ(agent.wait(10), 2) << agent.output();
  EXPECT_NE(agent.output().find("(--drop-rate) must be in [0, 1), got"), std::string::npos)
      << agent.output();
}

// Unsigned on a URL that leaves the host, anyone on the LAN acts for any slot: the server used to
// warn only, and its clients said nothing (issue 36, item 9).
TEST(BadInput, AnUnsignedServerOnALanUrlIsRefusedAndItsClientsSaySo) {
  const std::string dir = temp_dir(), secret = dir + "/secret";
  protocol::write_new_secret(secret);
  const std::string lan = "udpm://239.255.76.67:7667?ttl=1";
  auto serve = [&](std::vector<std::string> extra) {
    std::vector<std::string> argv = {program("olympics-server"),
                                     "serve",
                                     "--lcm-url",
                                     lan,
                                     "--results",
                                     dir + "/r.db",
                                     "--dry-run"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    auto p = std::make_unique<Process>(argv, dir + "/serve.log");
    p->wait(10);
    return p;
  };
  auto refused = serve({});
  EXPECT_EQ(refused->wait(1), 2) << refused->output();
  EXPECT_NE(refused->output().find("reaches the LAN (ttl > 0) but no secret is given"),
            std::string::npos)
      << refused->output();
  EXPECT_NE(refused->output().find("--unsigned-lan"), std::string::npos) << refused->output();
  auto trusted = serve({"--unsigned-lan"});
  EXPECT_EQ(trusted->wait(1), 0) << trusted->output();
  auto secured = serve({"--secret", secret});
  EXPECT_EQ(secured->wait(1), 0) << secured->output();
  Process agent({program("olympics-agent"), "--lcm-url", lan, "--match", "srv-x-1", "--slots", "0",
                 "--timeout", "1"},
                dir + "/agent.log");
  agent.wait(30);
  EXPECT_NE(agent.output().find("NO SECRET on " + lan), std::string::npos) << agent.output();
}

TEST(Config, TheExampleConfigLoadsAndFlagsOverrideIt) {
  std::string dir = temp_dir();
  Process p({program("olympics-server"), "serve", "--config",
             std::string(OLYMPICS_SOURCE_DIR) + "/deploy/olympics-server.example.toml",
             "--capacity", "7", "--dry-run"},
            dir + "/out.log");
  EXPECT_EQ(p.wait(10), 0) << p.output();
  EXPECT_NE(p.output().find("config ok: id server_a"), std::string::npos) << p.output();
  EXPECT_NE(p.output().find("capacity 7"), std::string::npos) << p.output();
  EXPECT_NE(p.output().find("deadline 1000 ms, 5 missed ticks"), std::string::npos) << p.output();
}

}  // namespace
}  // namespace olympics::testing
