// Replays re-run a match bit for bit; LCM event logs play back with lcm-logplayer; realtime
// matches keep the 30 Hz clock.
#include <cstdlib>
#include <fstream>

#include "channels.h"
#include "server_fixture.h"
#include "transport.h"

namespace olympics::testing {
namespace {

nlohmann::json play_1v1(ServerFixture& server, const std::string& id,
                        std::vector<std::string> extra = {}) {
  std::vector<std::string> a = {"--request-id", id,       "--slots",       "0",
                                "--policy",     "random", "--policy-seed", "1"};
  std::vector<std::string> b = {"--request-id", id, "--slots", "1", "--policy", "zero"};
  a.insert(a.end(), extra.begin(), extra.end());
  b.insert(b.end(), extra.begin(), extra.end());
  auto p = server.agent("a", a), q = server.agent("b", b);
  EXPECT_EQ(p->wait(60), 0) << p->output();
  EXPECT_EQ(q->wait(60), 0) << q->output();
  return ServerFixture::agent_result(*p);
}

TEST(Replay, ReplayCommandReproducesTheMatchAndCatchesTampering) {
  ServerFixture server;
  auto r = play_1v1(server, "rp", {"--seed", "9"});
  const std::string file =
      server.dir() + "/replays/" + r.at("match_id").get<std::string>() + ".replay";
  Process check({program("olympics-server"), "replay", file}, server.dir() + "/replay.log");
  EXPECT_EQ(check.wait(60), 0) << check.output();
  EXPECT_NE(check.output().find("REPRODUCED: identical result and final state"), std::string::npos);

  // Change one recorded action: the re-run must notice.
  std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
  f.seekg(0, std::ios::end);
  const auto end = f.tellg();
  f.seekp(end - std::streamoff(4 * 100));
  const float changed = 0.9f;
  f.write(reinterpret_cast<const char*>(&changed), sizeof changed);
  f.close();
  Process tampered({program("olympics-server"), "replay", file}, server.dir() + "/tampered.log");
  EXPECT_EQ(tampered.wait(60), 1) << tampered.output();
  EXPECT_NE(tampered.output().find("MISMATCH"), std::string::npos) << tampered.output();
  EXPECT_NE(tampered.output().find("state_hash: recorded"), std::string::npos);

  std::ofstream(server.dir() + "/junk.replay") << "not a replay\n";
  Process junk({program("olympics-server"), "replay", server.dir() + "/junk.replay"},
               server.dir() + "/junk.log");
  EXPECT_EQ(junk.wait(10), 2);
  EXPECT_NE(junk.output().find("is not a replay file"), std::string::npos) << junk.output();
}

TEST(Replay, LcmLogOfTheMatchPlaysBackWithLcmLogplayer) {
  ServerFixture server({"--lcm-logs"});
  auto r = play_1v1(server, "log");
  const std::string log =
      server.dir() + "/replays/" + r.at("match_id").get<std::string>() + ".lcmlog";
  // Play it onto a fresh port and count the observation batches that arrive.
  const std::string url = unique_lcm_url();
  protocol::Transport listener{protocol::TransportOptions(url)};
  int observations = 0;
  listener.subscribe(std::string(protocol::kObsPrefix) + ".*",
                     [&](const std::string&, const std::uint8_t*, int) { ++observations; });
  setenv("LCM_DEFAULT_URL", url.c_str(), 1);
  Process player({"/usr/bin/lcm-logplayer", "--speed=50", log}, server.dir() + "/player.log");
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (player.running() && std::chrono::steady_clock::now() < deadline) listener.handle(20);
  while (listener.handle(50)) {
  }
  EXPECT_EQ(player.wait(5), 0) << player.output();
  // Every tick sends one observation batch to each of the two clients (plus any resends).
  EXPECT_GE(observations, 2 * (r.at("ticks").get<int>() + 1));
}

TEST(Replay, RealtimeMatchKeepsTheThirtyHertzClock) {
  ServerFixture server;
  auto r = play_1v1(server, "rt", {"--realtime", "--time-limit", "1"});
  const int ticks = r.at("ticks");
  auto stored = server.store()->find(r.at("match_id"));
  ASSERT_TRUE(stored);
  EXPECT_TRUE(stored->realtime);
  // Wall time follows the clock: at least ticks / 30 s, where a lockstep match of zero-thinking
  // clients takes a fraction of that. (How closely it keeps the clock on a loaded machine is a
  // benchmark's question: olympics-bench soak.)
  EXPECT_GE(stored->wall_time_s, ticks / 30.0 - 0.05);
}

}  // namespace
}  // namespace olympics::testing
