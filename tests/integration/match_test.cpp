// Real matches between separate agent processes over LCM (udpm on loopback), results in SQLite.
#include <csignal>
#include <thread>

#include "match_client.h"
#include "server_fixture.h"

namespace olympics::testing {
namespace {

void expect_stored_like_printed(ServerFixture& server, const nlohmann::json& printed,
                                const std::vector<std::string>& agents) {
  auto store = server.store();
  auto stored = store->find(printed.at("match_id"));
  ASSERT_TRUE(stored.has_value()) << "match not in " << server.results_path();
  EXPECT_EQ(stored->ticks, printed.at("ticks").get<int>());
  EXPECT_EQ(stored->reason, printed.at("reason").get<std::string>());
  EXPECT_EQ(stored->winner_team, printed.at("winner_team").get<int>());
  ASSERT_EQ(stored->participants.size(), agents.size());
  for (size_t s = 0; s < agents.size(); ++s) EXPECT_EQ(stored->participants[s].agent, agents[s]);
  auto scores = printed.at("scores").get<std::vector<double>>();
  ASSERT_EQ(stored->scores.size(), scores.size());
  for (size_t t = 0; t < scores.size(); ++t) EXPECT_FLOAT_EQ(stored->scores[t], scores[t]);
}

TEST(Match, OneVsOneBetweenTwoAgentProcessesEndsAndIsStored) {
  ServerFixture server;
  auto alice = server.agent(
      "alice", {"--request-id", "m1", "--slots", "0", "--policy", "zero", "--seed", "3"});
  auto bob = server.agent(
      "bob", {"--request-id", "m1", "--slots", "1", "--policy", "random", "--seed", "3"});
  ASSERT_EQ(alice->wait(60), 0) << alice->output();
  ASSERT_EQ(bob->wait(60), 0) << bob->output();
  auto a = ServerFixture::agent_result(*alice), b = ServerFixture::agent_result(*bob);
  EXPECT_EQ(a, b);  // both saw the same result
  EXPECT_GT(a.at("ticks").get<int>(), 0);
  EXPECT_EQ(a.at("slot_team"), nlohmann::json({0, 1}));
  expect_stored_like_printed(server, a, {"alice", "bob"});
}

TEST(Match, TwoVsTwoBetweenFourAgentProcesses) {
  ServerFixture server;
  std::vector<std::unique_ptr<Process>> agents;
  const std::vector<std::string> names = {"a0", "a1", "b0", "b1"};
  for (int s = 0; s < 4; ++s)
    agents.push_back(server.agent(
        names[s], {"--request-id", "m2", "--mode", "2v2", "--slots", std::to_string(s), "--policy",
                   s % 2 ? "random" : "zero", "--policy-seed", std::to_string(s)}));
  for (auto& a : agents) ASSERT_EQ(a->wait(60), 0) << a->output();
  auto r = ServerFixture::agent_result(*agents[0]);
  EXPECT_EQ(r.at("slot_team"), nlohmann::json({0, 0, 1, 1}));
  EXPECT_EQ(r.at("scores").size(), 2u);
  expect_stored_like_printed(server, r, names);
}

// The same sync match with and without 10% of datagrams dropped (server and agents both drop)
// gives the identical result and the identical final physical state.
TEST(Match, SyncResultIsIdenticalWithTenPercentLoss) {
  auto play = [](bool lossy) {
    const std::string rate = lossy ? "0.1" : "0";
    ServerFixture server({"--drop-rate", rate, "--drop-seed", "11"});
    std::vector<std::string> common = {"--request-id", "loss", "--mode",      "1v1",
                                       "--seed",       "5",    "--policy",    "random",
                                       "--time-limit", "4",    "--drop-rate", rate};
    auto x = common, y = common;
    x.insert(x.end(), {"--slots", "0", "--policy-seed", "21", "--drop-seed", "12"});
    y.insert(y.end(), {"--slots", "1", "--policy-seed", "22", "--drop-seed", "13"});
    auto p0 = server.agent("x", x), p1 = server.agent("y", y);
    EXPECT_EQ(p0->wait(90), 0) << p0->output();
    EXPECT_EQ(p1->wait(90), 0) << p1->output();
    auto r = ServerFixture::agent_result(*p0);
    auto replay = server.replay(r.at("match_id"));
    return std::make_pair(r, replay.header.at("result"));
  };
  auto [clean, clean_replay] = play(false);
  auto [lossy, lossy_replay] = play(true);
  for (const char* key : {"ticks", "reason", "winner_team", "scores"})
    EXPECT_EQ(clean.at(key), lossy.at(key)) << key;
  EXPECT_EQ(clean_replay.at("state_hash"), lossy_replay.at("state_hash"));
  EXPECT_GT(clean.at("ticks").get<int>(), 3);
}

TEST(Match, KilledClientForfeitsAndTheServerKeepsServing) {
  // A deadline far beyond the survivor's 40 ms of thought, however loaded the machine; the dead
  // client misses 3 of them (or goes silent for 5 s) and forfeits.
  ServerFixture server({"--action-deadline-ms", "1000", "--max-missed-ticks", "3"});
  auto stay = server.agent(
      "stays", {"--request-id", "k1", "--slots", "0", "--think-ms", "40", "--time-limit", "30"});
  auto dies = server.agent(
      "dies", {"--request-id", "k1", "--slots", "1", "--think-ms", "40", "--time-limit", "30"});
  ASSERT_TRUE(dies->wait_for_output("joined", 60)) << dies->output();
  ASSERT_TRUE(stay->wait_for_output("joined", 60)) << stay->output();
  dies->signal(SIGKILL);
  ASSERT_EQ(stay->wait(30), 0) << stay->output();
  auto r = ServerFixture::agent_result(*stay);
  EXPECT_NE(r.at("reason").get<std::string>().find("forfeit: agent \"dies\""), std::string::npos)
      << r;
  EXPECT_EQ(r.at("winner_team"), 0);
  auto stored = server.store()->find(r.at("match_id"));
  ASSERT_TRUE(stored);
  EXPECT_EQ(stored->reason, r.at("reason").get<std::string>());
  // The server is still up and plays the next match to its end.
  auto p = server.agent("next0", {"--request-id", "k2", "--slots", "0"});
  auto q = server.agent("next1", {"--request-id", "k2", "--slots", "1"});
  EXPECT_EQ(p->wait(60), 0) << p->output();
  EXPECT_EQ(q->wait(60), 0) << q->output();
  EXPECT_EQ(server.store()->recent(10, "").size(), 2u);
}

// One client per match, owning both slots (a training client's usual shape): 50 clients, each
// with its own LCM socket, play 50 matches that all run at once.
TEST(Match, FiftyConcurrentMatchesOnOneServerComplete) {
  ServerFixture server({"--capacity", "64"});
  constexpr int kMatches = 50;
  std::atomic<int> at_barrier{0}, completed{0};
  std::vector<std::thread> players;
  std::vector<std::string> failures(kMatches);
  for (int m = 0; m < kMatches; ++m)
    players.emplace_back([&, m] {
      try {
        client::ClientOptions o;
        o.lcm_url = server.url();
        o.agent_name = "p" + std::to_string(m);
        client::MatchClient c(o);
        client::MatchRequest req;
        req.request_id = "many-" + std::to_string(m);
        req.time_limit_s = 1.0;
        auto created = c.request_match(req, 60);
        c.join(created.match_id, {0, 1}, 60);
        // Every match has started before any plays its first tick: they run concurrently.
        ++at_barrier;
        while (at_barrier < kMatches) std::this_thread::sleep_for(std::chrono::milliseconds(5));
        std::vector<std::vector<float>> zero(2, std::vector<float>(created.action_size, 0.0f));
        while (auto obs = c.next(60)) {
          if (obs->all_done()) break;
          c.act(obs->tick, zero);
        }
        c.wait_result(60);
        ++completed;
      } catch (const std::exception& e) {
        failures[m] = e.what();
        ++at_barrier;
      }
    });
  for (auto& t : players) t.join();
  for (const auto& f : failures) EXPECT_EQ(f, "");
  EXPECT_EQ(completed, kMatches);
  auto stored = server.store()->recent(100, "");
  EXPECT_EQ(stored.size(), static_cast<size_t>(kMatches));
  for (const auto& m : stored) EXPECT_EQ(m.reason, "time_limit");  // played to the end
}

}  // namespace
}  // namespace olympics::testing
