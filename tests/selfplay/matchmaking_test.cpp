#include "matchmaking.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

namespace olympics::selfplay {
namespace {

// Entrants: 0, 1 bots; 2, 3, 4 snapshots v1..v3 (4 is the latest, and itself as an opponent).
Roster roster() { return {4, {3, 2}, {0, 1}, 4}; }

std::map<int, int> tally(const SelfplayOptions& o, const PayoffMatrix& payoff, int n) {
  std::map<int, int> counts;
  for (int game = 0; game < n; ++game) ++counts[choose_opponent(o, roster(), payoff, game, 11, {})];
  return counts;
}

void expect_share(int count, int n, double p) {
  const double sd = std::sqrt(n * p * (1 - p));
  EXPECT_NEAR(count, n * p, 4 * sd + 1e-9);
}

TEST(Matchmaking, LatestPlaysItself) {
  SelfplayOptions o;
  o.strategy = "latest";
  EXPECT_EQ(tally(o, PayoffMatrix(5), 100)[4], 100);
}

TEST(Matchmaking, MlAgentsPlaysLatestWithRatioElseTheWindow) {
  SelfplayOptions o;
  o.strategy = "mlagents:0.3";
  const int n = 4000;
  auto c = tally(o, PayoffMatrix(5), n);
  expect_share(c[4], n, 0.3);
  expect_share(c[3], n, 0.35);
  expect_share(c[2], n, 0.35);
  EXPECT_EQ(c[0] + c[1], 0);
}

TEST(Matchmaking, BotShareComesFirst) {
  SelfplayOptions o;
  o.strategy = "latest";
  o.bot_share = 0.2;
  const int n = 4000;
  auto c = tally(o, PayoffMatrix(5), n);
  expect_share(c[0], n, 0.1);
  expect_share(c[1], n, 0.1);
  expect_share(c[4], n, 0.8);
}

TEST(Matchmaking, PfspFollowsThePayoff) {
  PayoffMatrix payoff(5, 1.0);
  for (int k = 0; k < 4; ++k)
    payoff.record(4, 3, 0.0), payoff.record(4, 2, 1.0);  // loses to v2, beats v1
  SelfplayOptions o;
  o.strategy = "pfsp:hard";
  const int n = 4000;
  auto c = tally(o, payoff, n);
  // weights: v2 (1-0)^2 = 1, v1 (1-1)^2 = 0, bots unknown 0.5 -> 0.25 each; total 1.5
  expect_share(c[3], n, 1 / 1.5);
  EXPECT_EQ(c[2], 0);
  expect_share(c[0], n, 0.25 / 1.5);
}

TEST(Matchmaking, AlternatingFreezesTheOpponentPerBlock) {
  SelfplayOptions o;
  o.strategy = "alternating:3";
  std::vector<Game> games;
  Game first;
  first.home = 4, first.away = 2;  // the block's first game froze entrant 2
  games.push_back(first);
  EXPECT_EQ(choose_opponent(o, roster(), PayoffMatrix(5), 1, 1, games), 2);
  EXPECT_EQ(choose_opponent(o, roster(), PayoffMatrix(5), 2, 1, games), 2);
  EXPECT_EQ(choose_opponent(o, roster(), PayoffMatrix(5), 3, 1, games), 4);  // a new block
}

TEST(Matchmaking, ALiveLearnerMeetsItsSnapshotsAndTheBotsNeverItself) {
  // Entrants: 0, 1 bots; 2, 3, 4 snapshots v1..v3; 5 the live learner.
  const Roster live{5, {4, 3, 2}, {0, 1}, 4};
  SelfplayOptions o;
  o.strategy = "latest";
  EXPECT_EQ(choose_opponent(o, live, PayoffMatrix(6), 0, 1, {}), 4) << "its newest snapshot";
  o.strategy = "pfsp:hard";
  PayoffMatrix payoff(6);
  for (int k = 0; k < 20; ++k) payoff.record(5, 1, 1.0);  // it beats bot 1 every time
  std::map<int, int> counts;
  for (int game = 0; game < 400; ++game) ++counts[choose_opponent(o, live, payoff, game, 3, {})];
  EXPECT_EQ(counts.count(5), 0u) << "never itself";
  EXPECT_LT(counts[1], counts[0]) << "PFSP hard: less of the bot it always beats";
  EXPECT_GT(counts[4] + counts[3] + counts[2], 0);
  o.strategy = "latest";
  EXPECT_EQ(choose_opponent(o, Roster{5, {}, {}, -1}, PayoffMatrix(6), 0, 1, {}), -1)
      << "nothing published yet: wait";
}

TEST(Matchmaking, UnknownStrategyAndVersions) {
  SelfplayOptions o;
  o.strategy = "roulette";
  EXPECT_THROW(choose_opponent(o, roster(), PayoffMatrix(5), 0, 1, {}), std::invalid_argument);
  EXPECT_EQ(snapshot_version("policy-v12.safetensors"), 12);
  EXPECT_EQ(snapshot_version("v3.safetensors"), 3);
  EXPECT_EQ(snapshot_version("notes.txt"), -1);
}

TEST(Matchmaking, TheSchedulerSeesASnapshotTheMomentItsNameAppears) {
  // A live learner publishes a snapshot per update, and a short game can end within
  // milliseconds of the last decision: the next decision must already see it.
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("olympics-snapshots-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  SelfplayOptions o;
  o.snapshots_dir = dir.string(), o.strategy = "latest", o.learner = "lt";
  SelfplayScheduler scheduler(o);
  TournamentSpec spec;
  spec.entrants = {{"lt", "live:lt", 0}};
  std::vector<Pairing> out;
  EXPECT_EQ(scheduler.schedule(spec, {}, out), Scheduler::Verdict::Wait) << "nothing published";
  std::ofstream(dir / "policy-v00001.safetensors") << "x";
  std::ofstream(dir / "policy-v00002.safetensors.partial") << "x";  // still being written
  ASSERT_EQ(scheduler.schedule(spec, {}, out), Scheduler::Verdict::Added);
  ASSERT_EQ(spec.entrants.size(), 2u) << "the finished snapshot only";
  EXPECT_EQ(spec.entrants[1].name, "mlp-policy-v00001");
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].home, 0);
  EXPECT_EQ(out[0].away, 1);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace olympics::selfplay
