// The scripted racket player's serve (`start: "serve"`, control/serve_plan.h) against the
// referee: the first serve of each seed's 1v1 match, both players scripted. Tuned on seeds 1-40;
// the tests use seeds 201-220. OLYMPICS_SERVE_FIGURE_SEEDS=106001-106300 measures the figure of
// docs/racket-sports.md instead (legal serves per serve with a Wilson 95% interval, per sport;
// OLYMPICS_SERVE_FIGURE_MODE=2v2 for doubles).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/control_rate.h"
#include "registry.h"
#include "scripted_racket.h"

namespace olympics::client {
namespace {

// How a serve went: "legal" (it landed in, so the receiver had to play it), "fault", "let", or
// what else ended it ("point": e.g. a fall before it landed).
struct ServeTally {
  int serves = 0, legal = 0, faults = 0, lets = 0, other = 0;
};

// Plays `sport` (1v1 or 2v2) with serves from `seed` until its first serve is decided; adds it to
// `tally`.
void first_serve(const std::string& sport, std::uint64_t seed, ServeTally& tally,
                 const std::string& mode = "1v1") {
  auto match = sports::sport_or_throw(sport).create({mode, seed, 20.0, {{"start", "serve"}}});
  const auto layout = ObservationLayout::from_blocks(match->layout().observation);
  const int n = match->slot_count();
  std::vector<ScriptedRacketPolicy> players(n);
  for (auto& p : players) p.start({sport, mode, core::kControlDt, layout, 69});
  std::vector<std::vector<float>> obs(n, std::vector<float>(match->obs_size())),
      act(n, std::vector<float>(69));
  std::vector<std::span<const float>> acts(act.begin(), act.end());
  int receiver_side = 0;  // the x sign of the receiver's half, once the toss is seen
  bool tossed = false;
  while (!match->outcome().match_over) {
    for (int s = 0; s < n; ++s) {
      match->observe(s, obs[s]);
      players[s].act(obs[s], act[s]);
    }
    match->step(acts);
    // This tick's calls, the serve's outcome judged on all of them (a bounce out and its fault
    // come in the same tick).
    bool bounced_in = false, point = false;
    for (const auto& ev : match->outcome().info.value("events", nlohmann::json::array())) {
      const std::string call = ev.value("call", "");
      if (call == "toss") {
        tossed = true;
        receiver_side = ev.at("slot").get<int>() < n / 2 ? 1 : -1;  // slots 0..n/2-1: team 0
      }
      if (!tossed) continue;
      if (call == "fault") return ++tally.faults, void(++tally.serves);
      if (call == "let") return ++tally.lets, void(++tally.serves);
      point = point || call == "point";
      bounced_in = bounced_in || (call == "bounce" && ev.at("x").get<double>() * receiver_side > 0);
    }
    if (bounced_in) return ++tally.legal, void(++tally.serves);
    if (point) return ++tally.other, void(++tally.serves);
  }
  ++tally.serves, ++tally.other;
}

ServeTally first_serves(const std::string& sport, std::uint64_t from, std::uint64_t to,
                        const std::string& mode = "1v1") {
  ServeTally t;
  for (std::uint64_t seed = from; seed <= to; ++seed) first_serve(sport, seed, t, mode);
  std::printf("%s %s seeds %llu-%llu: %d legal of %d serves (%d faults, %d lets, %d other)\n",
              sport.c_str(), mode.c_str(), static_cast<unsigned long long>(from),
              static_cast<unsigned long long>(to), t.legal, t.serves, t.faults, t.lets, t.other);
  return t;
}

TEST(ScriptedRacketServe, TableTennisServesLandLegally) {
  const ServeTally t = first_serves("table_tennis", 201, 220);
  EXPECT_EQ(t.serves, 20);
  EXPECT_GE(t.legal, 16);  // tuning seeds 1-40: 40 of 40
}

// Tennis: the serve the planner finds asks the face for about 9 m/s (a ball at about 12 m/s into
// a box some 15 m away), more than this arm swings (docs/racket-sports.md: the arc's face moves at
// a median 3.6 m/s): no scripted tennis serve lands in yet. What is checked is that each toss is
// called (a fault, then the double fault), so served tennis points end.
TEST(ScriptedRacketServe, TennisServesAreCalled) {
  const ServeTally t = first_serves("tennis", 201, 220);
  EXPECT_EQ(t.serves, 20);
  EXPECT_EQ(t.legal + t.faults + t.lets, 20);
}

TEST(ScriptedRacketServe, OneVsOneWithServesPlaysPoints) {
  auto match = sports::sport_or_throw("table_tennis")
                   .create({"1v1", 1, 120.0, {{"start", "serve"}, {"points_per_game", 5}}});
  const auto layout = ObservationLayout::from_blocks(match->layout().observation);
  ScriptedRacketPolicy players[2];
  for (auto& p : players) p.start({"table_tennis", "1v1", core::kControlDt, layout, 69});
  std::vector<float> obs[2] = {std::vector<float>(match->obs_size()),
                               std::vector<float>(match->obs_size())};
  std::vector<float> act[2] = {std::vector<float>(69), std::vector<float>(69)};
  int points = 0, tosses = 0, good_serve_points = 0, hits = 0;
  while (!match->outcome().match_over) {
    for (int s = 0; s < 2; ++s) {
      match->observe(s, obs[s]);
      players[s].act(obs[s], act[s]);
    }
    match->step({std::span<const float>(act[0]), std::span<const float>(act[1])});
    for (const auto& ev : match->outcome().info.value("events", nlohmann::json::array())) {
      const std::string call = ev.value("call", "");
      tosses += call == "toss";
      hits += call == "hit";
      if (call == "point") {
        ++points;
        good_serve_points += ev.value("reason", "") != "fault";
      }
    }
  }
  std::printf("%d points, %d tosses, %d hits, %d points past the serve; %s\n", points, tosses, hits,
              good_serve_points, match->outcome().reason.c_str());
  EXPECT_EQ(match->outcome().reason, "match_won");
  EXPECT_GE(points, 5);
  EXPECT_GE(tosses, points);  // one serve per point, and one more per let
  EXPECT_GE(good_serve_points, 2);
}

// The figure (docs/racket-sports.md), only when asked for: OLYMPICS_SERVE_FIGURE_SEEDS=A-B.
TEST(ScriptedRacketServe, FigureOnUnseenSeeds) {
  const char* seeds = std::getenv("OLYMPICS_SERVE_FIGURE_SEEDS");
  if (!seeds) GTEST_SKIP() << "set OLYMPICS_SERVE_FIGURE_SEEDS=106001-106300 to measure";
  const std::string s(seeds);
  const auto dash = s.find('-');
  ASSERT_NE(dash, std::string::npos) << "OLYMPICS_SERVE_FIGURE_SEEDS: give a range, A-B";
  const std::uint64_t from = std::stoull(s.substr(0, dash)), to = std::stoull(s.substr(dash + 1));
  for (const char* sport : {"table_tennis", "tennis"}) {
    const char* mode = std::getenv("OLYMPICS_SERVE_FIGURE_MODE");
    const ServeTally t = first_serves(sport, from, to, mode ? mode : "1v1");
    // Wilson 95% interval of legal / serves.
    const double n = t.serves, p = t.legal / n, z = 1.96, z2 = z * z;
    const double centre = (p + z2 / (2 * n)) / (1 + z2 / n);
    const double half = z * std::sqrt(p * (1 - p) / n + z2 / (4 * n * n)) / (1 + z2 / n);
    std::printf("FIGURE %s: legal serves %d of %d = %.1f%% (95%% %.1f-%.1f%%)\n", sport, t.legal,
                t.serves, 100 * p, 100 * (centre - half), 100 * (centre + half));
  }
}

}  // namespace
}  // namespace olympics::client
