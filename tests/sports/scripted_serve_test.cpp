// The scripted racket player's serve (`start: "serve"`, control/serve_plan.h) against the
// referee: the first serve of each seed's 1v1 match, both players scripted. Tuned on seeds 1-40;
// the tests use seeds 201-220. The figure on unseen seeds is `olympics-bench racket --serves N`
// (docs/racket-sports.md).
#include <gtest/gtest.h>

#include <cstdio>
#include <set>
#include <string>

#include "core/control_rate.h"
#include "racket_match_harness.h"
#include "registry.h"
#include "scripted_racket.h"

namespace olympics::client {
namespace {

// How a serve went, as the referee called it: in (`serve_in`), a `fault`, a `let`, or neither
// before the point ended (e.g. a fall).
struct ServeTally {
  int serves = 0, legal = 0, faults = 0, lets = 0, other = 0;
};

// Plays `sport` (1v1 or 2v2) with serves from `seed` until its first serve is called; adds it to
// `tally`.
void first_serve(const std::string& sport, std::uint64_t seed, ServeTally& tally,
                 const std::string& mode = "1v1") {
  ScriptedRacketPlay play(sport, {mode, seed, 20.0, {{"start", "serve"}}});
  ++tally.serves;
  while (!play.over()) {
    for (const auto& ev : play.tick()) {
      const std::string call = ev.value("call", "");
      if (call == "serve_in") return void(++tally.legal);
      if (call == "fault") return void(++tally.faults);
      if (call == "let") return void(++tally.lets);
      if (call == "point") return void(++tally.other);
    }
  }
  ++tally.other;
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

// Doubles (ITTF 2.6-2.7): from the server's right half onto the receiver's right half. The
// server stands on its right half, the toss near the right sideline: the planner tries own
// bounces across the right half nearer the centre line, sent up (the arm sends a ball at about
// 3.5 m/s), the face turned across for the arm's error. Tuning seeds 1-200: see
// docs/racket-sports.md; before, no doubles serve was legal (every toss not struck).
TEST(ScriptedRacketServe, TableTennisDoublesServesLandRightHalfToRightHalf) {
  const ServeTally t = first_serves("table_tennis", 201, 220, "2v2");
  EXPECT_EQ(t.serves, 20);
  EXPECT_GE(t.legal, 14);
}

// Tennis: a ball into the box from the baseline leaves the face at 12-15 m/s. The serve is swung
// on the rally's joint-space arc about the shoulder at the least planned face speed that lands
// in the box (10-11 m/s), the turn's inertial load held and the free arm swung against it, the
// face tilted down and turned right for the arm's error (docs/racket-sports.md, the tennis serve:
// tuning seeds 41-240, 18 of 200 in; before, none: the level straight swing asked 9 m/s of an arm
// that gave it 1.5). Every toss is still called (a fault, then the double fault), so served
// tennis points end.
TEST(ScriptedRacketServe, TennisServesAreCalled) {
  const ServeTally t = first_serves("tennis", 201, 220);
  EXPECT_EQ(t.serves, 20);
  EXPECT_EQ(t.legal + t.faults + t.lets, 20);
}

TEST(ScriptedRacketServe, TennisServeLandsInTheServiceBox) {
  const ServeTally t = first_serves("tennis", 201, 260);
  EXPECT_EQ(t.serves, 60);
  EXPECT_GE(t.legal, 2);  // before the arc serve none
}

// The serve's second round (docs/racket-sports.md): the server's swing is not held back while its
// legs keep it on its spot (the arm was readied by inverse kinematics until 0.5 s before contact,
// as for a ball the legs still walk to), and it meets the toss within 0.95 of the arm's reach.
// Tuning seeds 41-100: 7 of 60 first serves in; main before it 0.
TEST(ScriptedRacketServe, TennisServeSwungFromTheSpotLandsIn) {
  const ServeTally t = first_serves("tennis", 41, 100);
  EXPECT_EQ(t.serves, 60);
  EXPECT_GE(t.legal, 5);
}

// Every toss is met: the match's toss falls 0.85-0.9 m from the server's shoulder, and at the
// rally's 0.9 of the reach (0.85 m) no serve was planned for 4 of these 60 (seeds 62, 78, 94,
// 98), nor for 18 of 200 1v1 and 29 of 200 2v2 tuning seeds 41-240: the toss fell unstruck.
TEST(ScriptedRacketServe, TennisServeIsPlannedForEveryToss) {
  int tosses = 0, planned = 0;
  for (std::uint64_t seed = 41; seed <= 100; ++seed) {
    ScriptedRacketPlay play("tennis", {"1v1", seed, 20.0, {{"start", "serve"}}});
    bool served = false, called = false;
    while (!play.over() && !called) {
      const auto events = play.tick([&](int slot) {
        const auto& stroke = play.players[slot].stroke();
        served = served || (stroke && stroke->serve);
      });
      for (const auto& ev : events) {
        const std::string call = ev.value("call", "");
        called = called || call == "serve_in" || call == "fault" || call == "let";
      }
    }
    ++tosses;
    planned += served;
  }
  EXPECT_EQ(planned, tosses);
}

// The ad court (left of the centre mark, every other point): facing the net, no serve was even
// planned from there (the arm's arc about the shoulder sends the ball left; the box is to the
// right), so half a served match's points began with a double fault. Turned side-on there (the
// game's ad_serve_turn) the toss is beside the server: served 1v1 tuning seeds 1-8, ad-court
// tosses in 0 -> 13 of 56. Here seeds 201-204, the first 8 ad-court tosses of each (facing the
// net: 0 of 32).
TEST(ScriptedRacketServe, TennisAdCourtServesLandIn) {
  int ad_tosses = 0, ad_in = 0;
  for (std::uint64_t seed = 201; seed <= 204; ++seed) {
    ScriptedRacketPlay play("tennis", {"1v1", seed, 0.0, {{"start", "serve"}}});
    const int court_y = play.layout.offset("court_position", "y");
    int server = -1, seen = 0;
    bool ad = false, asked = false;
    while (!play.over() && seen < 8) {
      const auto events = play.tick([&](int slot) {
        // Its side of the centre mark, seen from its own half (left is +y), the tick after the
        // toss.
        if (asked && slot == server) ad = play.obs[slot][court_y] > 0, asked = false;
      });
      for (const auto& ev : events) {
        const std::string call = ev.value("call", "");
        if (call == "toss") server = ev.value("slot", -1), asked = true;
        if (server < 0 || !(call == "serve_in" || call == "fault" || call == "let")) continue;
        if (ad) ++seen, ad_in += call == "serve_in";
        server = -1;
      }
    }
    ad_tosses += seen;
  }
  std::printf("tennis 1v1 ad-court tosses: %d in of %d\n", ad_in, ad_tosses);
  EXPECT_EQ(ad_tosses, 32);
  EXPECT_GE(ad_in, 2);
}

// A table-tennis match to 5 with serves, scripted: it ends by score, with rallies past the serve
// (in 2v2 the four take the serve in turn, A1, B1, A2, B2).
void plays_points_with_serves(const std::string& mode) {
  ScriptedRacketPlay play("table_tennis",
                          {mode, 1, 120.0, {{"start", "serve"}, {"points_per_game", 5}}});
  const auto& match = play.match;
  int points = 0, tosses = 0, good_serve_points = 0, hits = 0;
  std::set<int> served_in;  // the slots whose serves landed in
  while (!play.over()) {
    for (const auto& ev : play.tick()) {
      const std::string call = ev.value("call", "");
      if (call == "serve_in") served_in.insert(ev.value("slot", -1));
      tosses += call == "toss";
      hits += call == "hit";
      if (call == "point") {
        ++points;
        good_serve_points += ev.value("reason", "") != "fault";
      }
    }
  }
  std::printf("%s: %d points, %d tosses, %d hits, %d points past the serve, %zu servers in; %s\n",
              mode.c_str(), points, tosses, hits, good_serve_points, served_in.size(),
              match->outcome().reason.c_str());
  EXPECT_EQ(match->outcome().reason, "match_won");
  EXPECT_GE(points, 5);
  EXPECT_GE(tosses, points);  // one serve per point, and one more per let
  EXPECT_GE(good_serve_points, 2);
  // Both sides' servers; in 2v2 at least three of the four (all four on seed 1).
  EXPECT_GE(served_in.size(), mode == "2v2" ? 3u : 2u);
}

TEST(ScriptedRacketServe, OneVsOneWithServesPlaysPoints) { plays_points_with_serves("1v1"); }

TEST(ScriptedRacketServe, DoublesWithServesPlaysPoints) { plays_points_with_serves("2v2"); }

}  // namespace
}  // namespace olympics::client
