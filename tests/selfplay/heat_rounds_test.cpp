// Swiss and knockout for heats of N > 2 entrants (heat_rounds.h): who is seated, who goes
// through, who rests, when the tournament ends; and the scheduler playing them round by round.
#include "heat_rounds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "scheduler.h"

namespace olympics::selfplay {
namespace {

std::vector<int> seats_of(const Pairing& p) { return p.seats; }

// Every heat's result: places by the seats' entrant index (the lower index first) unless
// `winner_last`, where the order is reversed (upsets).
std::vector<HeatResult> play(const std::vector<Pairing>& round, bool upsets = false) {
  std::vector<HeatResult> out;
  for (const auto& p : round) {
    HeatResult r{p.round, p.seats, {}};
    std::vector<int> sorted = p.seats;
    std::sort(sorted.begin(), sorted.end());
    if (upsets) std::reverse(sorted.begin(), sorted.end());
    for (int e : p.seats)
      r.places.push_back(
          static_cast<int>(std::find(sorted.begin(), sorted.end(), e) - sorted.begin()) + 1);
    out.push_back(r);
  }
  return out;
}

TEST(KnockoutHeats, EightInFoursAHeatRoundThenTheFinalOfItsTopTwos) {
  std::vector<HeatResult> results;
  const auto r0 = knockout_heats_round(8, 4, results);
  ASSERT_EQ(r0.size(), 2u);
  // Serpentine: seeds 0 1 | 1 0 | 0 1 | 1 0 across the two heats.
  EXPECT_EQ(seats_of(r0[0]), (std::vector<int>{0, 3, 4, 7}));
  EXPECT_EQ(seats_of(r0[1]), (std::vector<int>{1, 2, 5, 6}));
  EXPECT_EQ(r0[0].round, 0);
  EXPECT_EQ(r0[0].home, 0);
  EXPECT_EQ(r0[0].away, 3);
  // Upsets: the two lowest seeds of each heat go through.
  auto played = play(r0, true);
  results.insert(results.end(), played.begin(), played.end());
  const auto r1 = knockout_heats_round(8, 4, results);
  ASSERT_EQ(r1.size(), 1u) << "the final";
  std::vector<int> final_seats = r1[0].seats;
  std::sort(final_seats.begin(), final_seats.end());
  EXPECT_EQ(final_seats, (std::vector<int>{4, 5, 6, 7}));
  EXPECT_EQ(r1[0].round, 1);
  played = play(r1);
  results.insert(results.end(), played.begin(), played.end());
  EXPECT_TRUE(knockout_heats_round(8, 4, results).empty()) << "over after the final";
}

TEST(KnockoutHeats, AFieldThatDoesNotDivideRestsItsBestSeedsAndEveryHeatIsFull) {
  // 10 in heats of 4: seeds 0 and 1 rest; two heats, two of each through (6); then one heat
  // with seeds 0 and 1 resting again, two through; the final of 4.
  std::vector<HeatResult> results;
  std::vector<size_t> heats_per_round;
  for (int round = 0; round < 10; ++round) {
    const auto r = knockout_heats_round(10, 4, results);
    if (r.empty()) break;
    heats_per_round.push_back(r.size());
    for (const auto& p : r) {
      EXPECT_EQ(p.seats.size(), 4u);
      EXPECT_EQ(p.round, round);
      if (round < 2) {
        EXPECT_EQ(std::count(p.seats.begin(), p.seats.end(), 0), 0) << "seed 0 has a bye";
        EXPECT_EQ(std::count(p.seats.begin(), p.seats.end(), 1), 0) << "seed 1 has a bye";
      }
    }
    const auto played = play(r);
    results.insert(results.end(), played.begin(), played.end());
  }
  EXPECT_EQ(heats_per_round, (std::vector<size_t>{2, 1, 1}));
  EXPECT_EQ(knockout_advancing(10, 4), 2);
  EXPECT_EQ(knockout_advancing(8, 4), 2);
  EXPECT_EQ(knockout_advancing(5, 4), 3) << "one resting: three through make the final four";
  EXPECT_EQ(knockout_advancing(9, 8), 7);
  EXPECT_EQ(knockout_advancing(16, 8), 4);
}

TEST(KnockoutHeats, ATieAtTheCutGoesToTheBetterSeed) {
  const std::vector<HeatResult> results = {{0, {0, 3, 4, 7}, {1, 2, 2, 2}},
                                           {0, {1, 2, 5, 6}, {1, 1, 1, 1}}};
  const auto final_round = knockout_heats_round(8, 4, results);
  ASSERT_EQ(final_round.size(), 1u);
  std::vector<int> seats = final_round[0].seats;
  std::sort(seats.begin(), seats.end());
  EXPECT_EQ(seats, (std::vector<int>{0, 1, 2, 3}));
  const std::vector<HeatResult> no_places = {{0, {0, 3, 4, 7}, {}}, {0, {1, 2, 5, 6}, {}}};
  EXPECT_EQ(knockout_heats_round(8, 4, no_places)[0].seats.size(), 4u) << "no places: all tied";
}

TEST(SwissHeats, LaterRoundsAreDrawnByStanding) {
  std::vector<HeatResult> results;
  const auto r0 = swiss_heats_round(8, 4, results);
  ASSERT_EQ(r0.size(), 2u);
  EXPECT_EQ(seats_of(r0[0]), (std::vector<int>{0, 3, 4, 7}));
  // Round 0 won by the high numbers: 7 and 6 win their heats (3 points), 5 and 4 second (2)...
  auto played = play(r0, true);
  results.insert(results.end(), played.begin(), played.end());
  const auto points = swiss_heat_points(8, 4, results);
  EXPECT_EQ(points, (std::vector<double>{0, 0, 1, 1, 2, 2, 3, 3}));
  const auto r1 = swiss_heats_round(8, 4, results);
  ASSERT_EQ(r1.size(), 2u);
  EXPECT_EQ(seats_of(r1[0]), (std::vector<int>{6, 7, 4, 5})) << "the top four by points";
  EXPECT_EQ(seats_of(r1[1]), (std::vector<int>{2, 3, 0, 1}));
  played = play(r1);
  results.insert(results.end(), played.begin(), played.end());
  ASSERT_EQ(swiss_heats_round(8, 4, results).size(), 2u) << "round 3 of ceil(log2 8)";
  played = play(swiss_heats_round(8, 4, results));
  results.insert(results.end(), played.begin(), played.end());
  EXPECT_TRUE(swiss_heats_round(8, 4, results).empty());
}

TEST(SwissHeats, RestsGoToTheLowestStandingOfThoseWhoRestedLeast) {
  // 6 in heats of 4, 3 rounds: two rest each round, so each rests once.
  std::vector<HeatResult> results;
  std::map<int, int> rests;
  for (int round = 0; round < 3; ++round) {
    const auto r = swiss_heats_round(6, 4, results);
    ASSERT_EQ(r.size(), 1u);
    std::set<int> seated(r[0].seats.begin(), r[0].seats.end());
    for (int e = 0; e < 6; ++e) rests[e] += !seated.count(e);
    if (round == 0) {
      EXPECT_EQ(seated, (std::set<int>{0, 1, 2, 3})) << "the lowest seeds rest";
    }
    const auto played = play(r);
    results.insert(results.end(), played.begin(), played.end());
  }
  for (const auto& [e, n] : rests) EXPECT_EQ(n, 1) << "entrant " << e;
  EXPECT_TRUE(swiss_heats_round(6, 4, results).empty());
}

TournamentSpec spec_of(int entrants, const std::string& format) {
  TournamentSpec spec;
  spec.name = "t", spec.format = format, spec.mode = "competition_4", spec.sport = "long_jump";
  for (int i = 0; i < entrants; ++i) {
    std::string name = "e";
    name += std::to_string(i);
    spec.entrants.push_back({name, "zero", 1});
  }
  return spec;
}

TEST(HeatFormats, TheSchedulerPlaysKnockoutAndSwissHeatsRoundByRound) {
  for (const std::string format : {"knockout", "swiss"}) {
    auto spec = spec_of(8, format);
    auto scheduler = make_tournament_scheduler();
    std::vector<Game> games;
    int rounds = 0;
    for (;;) {
      std::vector<Pairing> out;
      const auto verdict = scheduler->schedule(spec, games, out);
      if (verdict == Scheduler::Verdict::Finished) break;
      ASSERT_EQ(verdict, Scheduler::Verdict::Added) << format;
      ASSERT_LT(rounds, 5) << format;
      for (const auto& p : out) {
        ASSERT_EQ(p.seats.size(), 4u);
        Game g;
        g.index = static_cast<int>(games.size()), g.round = p.round, g.home = p.home;
        g.away = p.away, g.seats = p.seats;
        games.push_back(g);
      }
      std::vector<Pairing> none;
      EXPECT_EQ(scheduler->schedule(spec, games, none), Scheduler::Verdict::Wait);
      for (auto& g : games) {
        if (g.status == GameStatus::Done) continue;
        g.status = GameStatus::Done;
        const auto r = play({{g.round, g.home, g.away, g.seats}});
        g.places = r[0].places;
      }
      ++rounds;
    }
    EXPECT_EQ(rounds, format == "knockout" ? 2 : 3) << format;
  }
}

}  // namespace
}  // namespace olympics::selfplay
