// Scene tracks (the viewer's data): every tick of a played match is recorded beside its replay,
// the poses are the simulation's (to the quantum), the track is derived data that re-running the
// replay writes again byte for byte, live viewers get it without holding up the match, and bad
// files are refused by name.
#include "scene_track.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "live_scenes.h"
#include "registry.h"
#include "server_fixture.h"

namespace olympics::testing {
namespace {

TEST(SceneTrack, FramesDecodeToTheSimulationsPosesWithinTheQuantum) {
  auto match = sports::sport_or_throw("tennis").create({"1v1", 3, 10, {}});
  server::SceneEncoder encoder;
  std::string records = encoder.header(*match, "tennis", {{"match_id", "m"}});
  std::vector<std::vector<float>> truth;
  std::vector<float> zero(match->action_size(), 0.0f), poses;
  for (int t = 0; t <= 40; ++t) {
    if (t > 0) match->step({zero, zero});
    records += encoder.frame(*match);
    match->scene_poses(poses);
    truth.push_back(poses);
  }
  records += encoder.result(*match);
  const server::SceneTrack track = server::decode_scene(records);
  EXPECT_EQ(track.header.at("sport"), "tennis");
  EXPECT_EQ(track.header.at("body_count").get<size_t>(), truth[0].size() / 7);
  ASSERT_EQ(track.frames.size(), truth.size());
  for (size_t f = 0; f < truth.size(); ++f) {
    EXPECT_EQ(track.frames[f].tick, static_cast<int>(f));
    for (size_t i = 0; i < truth[f].size(); ++i)
      ASSERT_NEAR(track.frames[f].poses[i], truth[f][i], i % 7 < 3 ? 0.0006 : 0.0001)
          << "frame " << f << " value " << i;
    EXPECT_EQ(track.frames[f].rewards.size(), 2 * (1 + match->reward_terms().size()));
  }
  EXPECT_EQ(track.result.at("ticks"), 40);
}

TEST(SceneTrack, LiveViewersGetTheHeaderTheNewestTickAndTheEndWithoutHoldingTheMatch) {
  // (Built with +=: GCC 12 warns wrongly about "F" + std::to_string(t).)
  auto tick = [](int t) {
    std::string record = "F";
    record += std::to_string(t);
    return record;
  };
  server::LiveScene live(nlohmann::json{{"match_id", "m"}});
  live.publish_header("Hheader");
  for (int t = 0; t < 200; ++t) live.publish_tick(t, tick(t));
  // A new viewer: the header and the newest tick only, not a backlog.
  auto first = live.wait(0, std::chrono::milliseconds(10));
  ASSERT_EQ(first.records.size(), 2u);
  EXPECT_EQ(first.records[0], "Hheader");
  EXPECT_EQ(first.records[1], "F199");
  // Keeping up: exactly what came since.
  live.publish_tick(200, "F200");
  live.publish_tick(201, "F201");
  auto next = live.wait(first.next, std::chrono::milliseconds(10));
  EXPECT_EQ(next.records, (std::vector<std::string>{"F200", "F201"}));
  // Far behind: skips to the newest tick (each frame is a whole pose).
  for (int t = 202; t < 400; ++t) live.publish_tick(t, tick(t));
  auto behind = live.wait(next.next, std::chrono::milliseconds(10));
  EXPECT_EQ(behind.records, (std::vector<std::string>{"F399"}));
  // Nothing new: waits no longer than asked.
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_TRUE(live.wait(behind.next, std::chrono::milliseconds(50)).records.empty());
  EXPECT_GE(std::chrono::steady_clock::now() - t0, std::chrono::milliseconds(40));
  live.end("Rresult");
  auto end = live.wait(behind.next, std::chrono::milliseconds(10));
  EXPECT_TRUE(end.ended);
  EXPECT_EQ(end.records.back(), "Rresult");
}

TEST(SceneTrack, EveryTickIsRecordedBesideTheReplayAndReRunningTheReplayWritesItAgain) {
  ServerFixture server;
  const std::vector<std::string> common = {"--request-id", "scene", "--sport",  "tennis",
                                           "--mode",       "1v1",   "--seed",   "4",
                                           "--time-limit", "4",     "--policy", "scripted"};
  auto a = common, b = common;
  a.insert(a.end(), {"--slots", "0"});
  b.insert(b.end(), {"--slots", "1"});
  auto p = server.agent("a", a), q = server.agent("b", b);
  ASSERT_EQ(p->wait(120), 0) << p->output();
  ASSERT_EQ(q->wait(120), 0) << q->output();
  const auto r = ServerFixture::agent_result(*p);
  const std::string id = r.at("match_id");
  const std::string dir = server.dir() + "/replays/";

  const std::string recorded = server::read_scene_file(dir + id + ".scene");
  const server::SceneTrack track = server::decode_scene(recorded);
  EXPECT_EQ(track.header.at("match_id"), id);
  EXPECT_EQ(track.header.at("agents"), nlohmann::json({"a", "b"}));
  ASSERT_EQ(static_cast<int>(track.frames.size()), r.at("ticks").get<int>() + 1);
  for (size_t f = 0; f < track.frames.size(); ++f)
    ASSERT_EQ(track.frames[f].tick, static_cast<int>(f));
  EXPECT_EQ(track.result.at("reason"), r.at("reason"));
  EXPECT_EQ(track.result.at("scores"), r.at("scores"));
  EXPECT_EQ(std::vector<float>(track.frames.back().scores),
            r.at("scores").get<std::vector<float>>());
  EXPECT_FALSE(track.events.empty()) << "the score and the calls are recorded";
  EXPECT_FALSE(std::filesystem::exists(dir + id + ".scene.part"));

  // Derived data: a replay without its track gets it back, byte for byte, by re-running.
  const std::string copy = server.dir() + "/copy.replay";
  std::filesystem::copy_file(dir + id + ".replay", copy);
  Process view({program("olympics-server"), "view", copy, "--export", server.dir() + "/m.html"},
               server.dir() + "/view.log");
  ASSERT_EQ(view.wait(120), 0) << view.output();
  EXPECT_NE(view.output().find("re-running the replay"), std::string::npos) << view.output();
  EXPECT_EQ(server::read_scene_file(server.dir() + "/copy.scene"), recorded);
  Process check({program("olympics-server"), "replay", dir + id + ".replay"},
                server.dir() + "/replay.log");
  EXPECT_EQ(check.wait(120), 0) << check.output();

  // The exported page is one file: scripts and data inline, nothing to fetch.
  std::ifstream page_in(server.dir() + "/m.html");
  const std::string page((std::istreambuf_iterator<char>(page_in)), {});
  EXPECT_NE(page.find("id=\"scene-data\""), std::string::npos);
  EXPECT_EQ(page.find("<script src="), std::string::npos);
  EXPECT_EQ(page.find("<link rel=\"stylesheet\""), std::string::npos);
}

TEST(SceneTrack, BadFilesAreRefusedByName) {
  ServerFixture server;
  std::ofstream(server.dir() + "/junk.scene") << "not zstd";
  Process junk({program("olympics-server"), "view", server.dir() + "/junk.scene", "--export",
                server.dir() + "/x.html"},
               server.dir() + "/junk.log");
  EXPECT_EQ(junk.wait(30), 2);
  EXPECT_NE(junk.output().find("is not a scene track"), std::string::npos) << junk.output();
  Process other({program("olympics-server"), "view", server.dir() + "/notes.txt"},
                server.dir() + "/other.log");
  EXPECT_EQ(other.wait(30), 2);
  EXPECT_NE(other.output().find("neither a .replay nor a .scene"), std::string::npos)
      << other.output();
}

}  // namespace
}  // namespace olympics::testing
