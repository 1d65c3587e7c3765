// With a deployment secret only its holders act: a secured match plays to its stored end; a
// client without the secret is told why it gets no answer; and an attacker on the network who
// copies a client id from the observations, forges results or announces a fake server changes
// nothing: its messages are dropped and counted.
#include "auth.h"

#include <atomic>
#include <random>
#include <thread>

#include "channels.h"
#include "league_store.h"
#include "olympics/action_batch_t.hpp"
#include "olympics/error_t.hpp"
#include "olympics/match_created_t.hpp"
#include "olympics/match_result_t.hpp"
#include "olympics/observation_batch_t.hpp"
#include "olympics/server_announce_t.hpp"
#include "server_fixture.h"
#include "transport.h"
#include "version.h"

namespace olympics::testing {
namespace {

std::string new_secret(const std::string& dir) {
  protocol::write_new_secret(dir + "/secret");
  return dir + "/secret";
}

// An attacker without the secret, on the same network, in a thread: it reads what anyone can
// read and sends what it likes (unsigned: it has no key).
class Attacker {
 public:
  explicit Attacker(const std::string& url) : transport_(protocol::TransportOptions(url)) {}
  ~Attacker() { stop(); }
  // Spoofs an action for every observation it sees, with the observed client's id.
  void spoof_actions() {
    transport_.subscribe(std::string(protocol::kObsPrefix) + ".*",
                         [this](const std::string&, const std::uint8_t* d, int n) {
                           auto b = protocol::decode<olympics::observation_batch_t>(d, n);
                           if (!b) return;
                           olympics::action_batch_t a;
                           a.protocol_version = protocol::kProtocolVersion;
                           a.match_id = b->match_id, a.client_id = b->client_id, a.tick = b->tick;
                           a.seq = b->seq + 1000, a.num_slots = b->num_slots, a.slots = b->slots;
                           a.action_size = 69;
                           std::uniform_real_distribution<float> u(-1, 1);
                           a.actions.assign(b->slots.size(), std::vector<float>(69));
                           for (auto& row : a.actions)
                             for (auto& x : row) x = u(rng_);
                           transport_.publish(protocol::action_channel(b->match_id), a);
                           ++sent_;
                         });
    start();
  }
  // Answers every match created with a forged result: team 1 won at tick 1.
  void forge_results() {
    transport_.subscribe(protocol::kCreated, [this](const std::string&, const std::uint8_t* d,
                                                    int n) {
      auto c = protocol::decode<olympics::match_created_t>(d, n);
      if (!c) return;
      olympics::match_result_t r;
      r.protocol_version = protocol::kProtocolVersion;
      r.match_id = c->match_id, r.server_id = c->server_id, r.sport = c->sport, r.mode = c->mode;
      r.ticks = 1, r.reason = "forged", r.winner_team = 1, r.num_teams = 2, r.scores = {0, 99};
      r.num_slots = c->num_slots, r.slot_team = c->slot_team;
      r.agent_names.assign(c->num_slots, "x"), r.policy_ids = r.agent_names;
      r.policy_versions = r.agent_names;
      for (int i = 0; i < 5; ++i) transport_.publish(protocol::kResult, r), ++sent_;
    });
    start();
  }
  // Announces a server "aaa" with room for 1000 matches, 10 times a second: without the secret
  // check, every real server would leave unaddressed requests to it.
  void fake_server() {
    start([this] {
      olympics::server_announce_t a;
      a.protocol_version = protocol::kProtocolVersion;
      a.server_id = "aaa", a.capacity = 1000, a.num_sports = 1, a.sports = {"sandbox"};
      transport_.publish(protocol::kAnnounce, a);
      ++sent_;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    });
  }
  // Sends, unsigned, two copies of every request and join it hears (the same ids, the signature
  // zeroed: it has no key). A server that answered them with a signed UNAUTHENTICATED naming
  // those ids would be an oracle: the real clients would believe their requests and joins
  // refused and give up.
  void echo_requests_and_joins() {
    for (const char* channel : {protocol::kRequest, protocol::kJoin})
      transport_.subscribe(channel, [this](const std::string& ch, const std::uint8_t* d, int n) {
        if (n < protocol::kSignatureBytes) return;
        std::vector<std::uint8_t> copy(d, d + n);
        std::fill(copy.end() - protocol::kSignatureBytes, copy.end(), std::uint8_t{0});
        for (int i = 0; i < 2; ++i) transport_.publish_raw(ch, copy.data(), n), ++sent_;
      });
    start();
  }
  // Sends the server's UNAUTHENTICATED hint, unsigned, 100 times a second.
  void forge_hints() {
    start([this] {
      olympics::error_t e;
      e.protocol_version = protocol::kProtocolVersion;
      e.code = "UNAUTHENTICATED", e.message = "signature check failed";
      transport_.publish(protocol::kError, e);
      ++sent_;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    });
  }
  long sent() const { return sent_; }
  void stop() {
    running_ = false;
    if (thread_.joinable()) thread_.join();
  }

 private:
  void start(std::function<void()> also = nullptr) {
    thread_ = std::thread([this, also] {
      while (running_) {
        transport_.handle(5);
        if (also) also();
      }
    });
  }
  protocol::Transport transport_;
  std::mt19937 rng_{5};
  std::atomic<bool> running_{true};
  std::atomic<long> sent_{0};
  std::thread thread_;
};

nlohmann::json play(ServerFixture& server, const std::string& id,
                    const std::vector<std::string>& extra) {
  std::vector<std::string> a = {"--request-id", id,  "--slots",  "0",     "--seed", "9",
                                "--time-limit", "2", "--policy", "random"};
  auto b = a;
  b[3] = "1";
  a.insert(a.end(), extra.begin(), extra.end());
  b.insert(b.end(), extra.begin(), extra.end());
  auto pa = server.agent(id + "-a", a), pb = server.agent(id + "-b", b);
  EXPECT_EQ(pa->wait(60), 0) << pa->output();
  EXPECT_EQ(pb->wait(60), 0) << pb->output();
  return ServerFixture::agent_result(*pa);
}

// The refusals a server counted, from the line it prints when it stops.
long unauthenticated_refused(ServerFixture& server) {
  server.server().signal(SIGTERM);
  server.server().wait(20);
  const std::string out = server.server().output();
  const auto at = out.find(" malformed and ");
  return at == std::string::npos ? -1 : std::stol(out.substr(at + 15));
}

TEST(Auth, ASecuredMatchPlaysAndAClientWithoutTheSecretIsToldWhy) {
  const std::string dir = temp_dir(), secret = new_secret(dir);
  ServerFixture server({"--secret", secret});
  EXPECT_NE(server.server().output().find("signed and checked"), std::string::npos);
  const auto r = play(server, "secured", {"--secret", secret});
  ASSERT_TRUE(r.contains("match_id")) << r.dump();
  EXPECT_TRUE(server.store()->find(r.at("match_id")).has_value());
  // It is told within seconds, and gives up at its timeout (the server's hint names nobody, so
  // anyone could send one: it is reported, never obeyed).
  auto stranger = server.agent("stranger", {"--request-id", "nope", "--slots", "0"});
  EXPECT_TRUE(stranger->wait_for_output("UNAUTHENTICATED", 5)) << stranger->output();
  EXPECT_NE(stranger->output().find("--secret"), std::string::npos) << stranger->output();
  EXPECT_NE(stranger->output().find("this client has none"), std::string::npos)
      << stranger->output();
  stranger->signal(SIGTERM);
  stranger->wait(10);
}

// A misconfigured client says what is wrong within seconds, not at its timeout; and the hint
// it learns it from cannot make a correctly configured client give up: anyone can send one.
TEST(Auth, AMisconfiguredClientSaysSoWithinSecondsAndAForgedHintEndsNoMatch) {
  const std::string dir = temp_dir(), secret = new_secret(dir), other = dir + "/other";
  protocol::write_new_secret(other);
  auto waiting = [&](const ServerFixture& to, const std::string& name,
                     std::vector<std::string> key) {
    std::vector<std::string> argv = {program("olympics-agent"),
                                     "--lcm-url",
                                     to.url(),
                                     "--name",
                                     name,
                                     "--request-id",
                                     name,
                                     "--slots",
                                     "0",
                                     "--timeout",
                                     "60"};
    argv.insert(argv.end(), key.begin(), key.end());
    return std::make_unique<Process>(argv, to.dir() + "/agent-" + name + ".log");
  };
  ServerFixture server({"--secret", secret}), open_server;
  for (auto& [to, name, key, says] :
       std::vector<std::tuple<ServerFixture*, std::string, std::vector<std::string>, std::string>>{
           {&server, "wrong", {"--secret", other}, "is not the server's"},
           {&server, "none", {}, "this client has none"},
           {&open_server, "signed", {"--secret", secret}, "or none"}}) {
    auto p = waiting(*to, name, key);
    EXPECT_TRUE(p->wait_for_output(says, 5)) << name << ":\n" << p->output();
    p->signal(SIGTERM);
    p->wait(10);
  }
  // Forged hints on an unsigned network (where a client reads them): the match plays on.
  Attacker forger(open_server.url());
  forger.forge_hints();
  while (forger.sent() < 20) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const auto r = play(open_server, "hinted", {});
  forger.stop();
  EXPECT_TRUE(r.contains("match_id")) << r.dump();
  EXPECT_GT(forger.sent(), 10);
}

TEST(Auth, SpoofedActionsWithACopiedClientIdChangeNothing) {
  const std::string dir = temp_dir(), secret = new_secret(dir);
  ServerFixture quiet({"--secret", secret});
  const auto control = play(quiet, "control", {"--secret", secret});
  ServerFixture server({"--secret", secret});
  Attacker attacker(server.url());
  attacker.spoof_actions();
  const auto attacked = play(server, "attacked", {"--secret", secret});
  attacker.stop();
  EXPECT_GT(attacker.sent(), 10);
  // The same seeds and policies: the same match, to the bit.
  ASSERT_TRUE(control.contains("match_id") && attacked.contains("match_id"));
  EXPECT_EQ(control.at("ticks"), attacked.at("ticks"));
  const auto hash = [](ServerFixture& s, const nlohmann::json& r) {
    return s.replay(r.at("match_id")).header.at("result").at("state_hash").get<std::uint64_t>();
  };
  EXPECT_EQ(hash(quiet, control), hash(server, attacked));
  EXPECT_GT(unauthenticated_refused(server), 10) << "the spoofed actions were dropped and counted";
}

TEST(Auth, ForgedResultsAndAFakeServerAreIgnored) {
  const std::string url = unique_lcm_url(), dir = temp_dir(), secret = new_secret(dir);
  ServerFixture alpha({"--secret", secret}, url, "", "alpha");
  Attacker forger(url), faker(url);
  forger.forge_results();
  faker.fake_server();
  const std::string db = dir + "/league.db";
  Process run({program("olympics-league"), "run", "--db", db, "--name", "cup", "--entrants",
               "zero,random:1,random:2", "--time-limit", "2", "--lcm-url", url, "--secret", secret,
               "--log-dir", dir, "--quiet"},
              dir + "/league.log");
  ASSERT_EQ(run.wait(120), 0) << run.output();
  forger.stop(), faker.stop();
  EXPECT_GT(forger.sent(), 0);
  selfplay::LeagueStore store(db);
  auto records = alpha.store();
  for (const auto& g : store.games("cup")) {
    EXPECT_NE(g.reason, "forged");
    EXPECT_EQ(g.server_id, "alpha") << "no game went to the fake server";
    auto m = records->find(g.match_id);
    ASSERT_TRUE(m) << g.match_id;
    EXPECT_EQ(g.reason, m->reason);
    EXPECT_EQ(g.home_score, m->winner_team == 0 ? 1.0 : m->winner_team == 1 ? 0.0 : 0.5);
  }
}

// The signed-error oracle (issue 36, item 1): an outsider copies the ids of every request and
// join into unsigned ones; the server answers them unsigned, so the real clients, which hold
// the secret, drop the answer, and their match plays to its end.
TEST(Auth, UnsignedCopiesOfRequestsAndJoinsEndNoClientsMatch) {
  const std::string dir = temp_dir(), secret = new_secret(dir);
  ServerFixture server({"--secret", secret});
  Attacker attacker(server.url());
  attacker.echo_requests_and_joins();
  const auto r = play(server, "victim", {"--secret", secret});
  attacker.stop();
  EXPECT_GT(attacker.sent(), 0);
  ASSERT_TRUE(r.contains("match_id")) << r.dump();
  EXPECT_TRUE(server.store()->find(r.at("match_id")).has_value());
}

// The same against a league: before, its first game's request was "refused" and the run stopped
// (exit 2, no game played).
TEST(Auth, UnsignedCopiesOfRequestsDoNotStopALeague) {
  const std::string url = unique_lcm_url(), dir = temp_dir(), secret = new_secret(dir);
  ServerFixture alpha({"--secret", secret}, url, "", "alpha");
  Attacker attacker(url);
  attacker.echo_requests_and_joins();
  const std::string db = dir + "/league.db";
  Process run({program("olympics-league"), "run", "--db", db, "--name", "cup", "--entrants",
               "zero,random:1", "--time-limit", "2", "--lcm-url", url, "--secret", secret,
               "--log-dir", dir, "--quiet"},
              dir + "/league.log");
  ASSERT_EQ(run.wait(120), 0) << run.output();
  attacker.stop();
  EXPECT_GT(attacker.sent(), 0);
  selfplay::LeagueStore store(db);
  EXPECT_FALSE(store.games("cup").empty());
  for (const auto& g : store.games("cup")) EXPECT_FALSE(g.match_id.empty());
}

// A client with another secret than its server's, or with none against a signed one, or with one
// against an unsigned server: its TIMEOUT says what is wrong, not only "is olympics-server
// running?" (issue 36, item 8: misconfiguration).
TEST(Auth, AClientWithTheWrongSecretIsToldWhyNothingAnswers) {
  const std::string dir = temp_dir(), secret = new_secret(dir);
  const std::string other = dir + "/other";
  protocol::write_new_secret(other);
  // An agent giving up after 3 s (the fixture's agents wait 30).
  auto agent = [&](const ServerFixture& to, const std::string& name, const std::string& key) {
    auto p = std::make_unique<Process>(
        std::vector<std::string>{program("olympics-agent"), "--lcm-url", to.url(), "--name", name,
                                 "--request-id", name, "--slots", "0", "--timeout", "3", "--secret",
                                 key},
        to.dir() + "/agent-" + name + ".log");
    EXPECT_EQ(p->wait(30), 2) << p->output();
    return p->output();
  };
  ServerFixture server({"--secret", secret});
  const std::string wrong = agent(server, "wrong", other);
  EXPECT_NE(wrong.find("TIMEOUT"), std::string::npos) << wrong;
  EXPECT_NE(wrong.find("failed the signature check"), std::string::npos) << wrong;
  ServerFixture open_server;
  const std::string against_unsigned = agent(open_server, "signed", secret);
  EXPECT_NE(against_unsigned.find("failed the signature check"), std::string::npos)
      << against_unsigned;
  EXPECT_NE(against_unsigned.find("or none"), std::string::npos) << against_unsigned;
}

// Two servers whose ids share a beginning: each plays its own matches and claims none of the
// other's ("a" answered UNKNOWN_MATCH to every join and action of "a-b"; '-' is now refused).
TEST(Auth, ServersWhoseIdsShareAPrefixKeepTheirOwnMatches) {
  const std::string url = unique_lcm_url();
  ServerFixture a({}, url, "", "a"), a_b({}, url, "", "a_b");
  for (const char* id : {"a_b", "a"}) {
    const auto r =
        play(id == std::string("a") ? a : a_b, std::string("to_") + id, {"--server", id});
    ASSERT_TRUE(r.contains("match_id")) << r.dump();
    EXPECT_EQ(r.at("match_id").get<std::string>().rfind(std::string(id) + "-", 0), 0u) << r;
  }
  a.server().signal(SIGTERM), a_b.server().signal(SIGTERM);
  a.server().wait(20), a_b.server().wait(20);
  EXPECT_EQ(a.server().output().find("UNKNOWN_MATCH"), std::string::npos) << a.server().output();
  EXPECT_EQ(a_b.server().output().find("UNKNOWN_MATCH"), std::string::npos);
}

}  // namespace
}  // namespace olympics::testing
