// Rating updates against values computed by hand (and matching OpenSkill's published example:
// a 1v1 between two new players gives the winner mu 27.635, sigma 8.0655).
#include "ratings.h"

#include <gtest/gtest.h>

#include <cmath>

namespace olympics::selfplay {
namespace {

TEST(WengLin, OneVersusOneWin) {
  auto r = rate_match({{SkillRating{}}, {SkillRating{}}}, {0, 1});
  EXPECT_NEAR(r[0][0].mu, 27.63523138347365, 1e-9);
  EXPECT_NEAR(r[0][0].sigma, 8.065506316323548, 1e-9);
  EXPECT_NEAR(r[1][0].mu, 22.36476861652635, 1e-9);
  EXPECT_NEAR(r[1][0].sigma, 8.065506316323548, 1e-9);
}

TEST(WengLin, DrawKeepsMuAndShrinksSigma) {
  auto r = rate_match({{SkillRating{}}, {SkillRating{}}}, {0, 0});
  EXPECT_NEAR(r[0][0].mu, 25.0, 1e-12);
  EXPECT_NEAR(r[1][0].mu, 25.0, 1e-12);
  EXPECT_NEAR(r[0][0].sigma, 8.065506316323548, 1e-9);
}

TEST(WengLin, TwoVersusTwoSharesTheUpdateByVariance) {
  auto r = rate_match({{SkillRating{}, SkillRating{30, 4}}, {SkillRating{}, SkillRating{20, 6}}},
                      {0, 1});
  EXPECT_NEAR(r[0][0].mu, 26.56938032232665, 1e-9);
  EXPECT_NEAR(r[0][0].sigma, 8.154440341723307, 1e-9);
  EXPECT_NEAR(r[0][1].mu, 30.36158522626406, 1e-9);  // low sigma: a small step
  EXPECT_NEAR(r[0][1].sigma, 3.9803801033006945, 1e-9);
  EXPECT_NEAR(r[1][0].mu, 23.43061967767335, 1e-9);
  EXPECT_NEAR(r[1][1].mu, 19.186433240905863, 1e-9);
  EXPECT_NEAR(r[1][1].sigma, 5.9261663388938075, 1e-9);
}

// Three new athletes ranked 1, 2, 3 (Bradley-Terry full pairing, every pair compared). By hand:
// sigma^2 = 625/9, beta^2 = 625/36, so c^2 = 2 sigma^2 + 2 beta^2 = 6250/36, c = 25 sqrt(10)/6;
// equal mu gives p = 1/2 for every pair. The first gains sigma^2/c (1/2 + 1/2) = 150/(9 sqrt 10)
// = 5.2704627669473; the second wins one and loses one: no change; the third loses it. Each
// pair shrinks the variance by gamma sigma^2/c^2 p (1-p) = (2/sqrt 10)(0.4)(1/4): sigma' =
// sigma sqrt(1 - 0.4/sqrt 10) for all three.
TEST(WengLin, ThreeAthletesRankedByHand) {
  auto r = rate_match({{SkillRating{}}, {SkillRating{}}, {SkillRating{}}}, {1, 2, 3});
  const double step = 150.0 / (9.0 * std::sqrt(10.0));
  const double sigma = 25.0 / 3.0 * std::sqrt(1.0 - 0.4 / std::sqrt(10.0));
  EXPECT_NEAR(step, 5.2704627669473, 1e-12);
  EXPECT_NEAR(r[0][0].mu, 25.0 + step, 1e-12);
  EXPECT_NEAR(r[1][0].mu, 25.0, 1e-12);
  EXPECT_NEAR(r[2][0].mu, 25.0 - step, 1e-12);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(r[i][0].sigma, sigma, 1e-12) << i;
  EXPECT_NEAR(sigma, 7.788474807872566, 1e-12);
}

// Two athletes share first place: each draws the other (score 1/2 = p) and beats the third, so
// each gains half the winner's step above; the third loses both.
TEST(WengLin, ATieForFirstSharesTheStep) {
  auto r = rate_match({{SkillRating{}}, {SkillRating{}}, {SkillRating{}}}, {1, 1, 2});
  const double step = 150.0 / (9.0 * std::sqrt(10.0));
  EXPECT_NEAR(r[0][0].mu, 25.0 + step / 2, 1e-12);
  EXPECT_NEAR(r[1][0].mu, 25.0 + step / 2, 1e-12);
  EXPECT_NEAR(r[2][0].mu, 25.0 - step, 1e-12);
  EXPECT_EQ(r[0][0].sigma, r[2][0].sigma);  // p = 1/2 everywhere: the same shrink
}

// Everyone failed (eight athletes, all first): a draw among all. No mu moves; every sigma shrinks
// by seven pairs' worth.
TEST(WengLin, AnEightWayTieIsADrawAmongAll) {
  std::vector<std::vector<SkillRating>> field(8, {SkillRating{}});
  auto r = rate_match(field, std::vector<int>(8, 1));
  const double sigma = 25.0 / 3.0 * std::sqrt(1.0 - 7 * 0.2 / std::sqrt(10.0));
  for (const auto& team : r) {
    EXPECT_NEAR(team[0].mu, 25.0, 1e-12);
    EXPECT_NEAR(team[0].sigma, sigma, 1e-12);
  }
}

// An upset among unequal ratings (mu 30, 25, 20, new sigmas; the 20 wins, the 30 is last):
// p_iq = 1 / (1 + exp((mu_q - mu_i) / c)), values worked through the formulas above in Python.
TEST(WengLin, AnUpsetAmongThreeMovesTheFavouriteMost) {
  auto r = rate_match({{SkillRating{30, 25.0 / 3}}, {SkillRating{}}, {SkillRating{20, 25.0 / 3}}},
                      {3, 2, 1});
  EXPECT_NEAR(r[0][0].mu, 23.280839537311664, 1e-9);
  EXPECT_NEAR(r[0][0].sigma, 7.835246152377416, 1e-9);
  EXPECT_NEAR(r[1][0].mu, 25.0, 1e-9);  // symmetric: beat one as strongly as it lost
  EXPECT_NEAR(r[1][0].sigma, 7.808273183269872, 1e-9);
  EXPECT_NEAR(r[2][0].mu, 26.719160462688336, 1e-9);
}

TEST(WengLin, RefusesMalformedMatches) {
  EXPECT_THROW(rate_match({{SkillRating{}}}, {0}), std::invalid_argument);
  EXPECT_THROW(rate_match({{SkillRating{}}, {}}, {0, 1}), std::invalid_argument);
}

TEST(Elo, WinDrawLoss) {
  auto win = elo_update(1500, 1400, 1.0);
  EXPECT_NEAR(win.a, 1511.5179200063076, 1e-9);  // 1500 + 32 (1 - 1/(1 + 10^(-100/400)))
  EXPECT_NEAR(win.b, 1400 - 11.5179200063076, 1e-9);
  auto draw = elo_update(1500, 1500, 0.5);
  EXPECT_DOUBLE_EQ(draw.a, 1500);
  auto loss = elo_update(1500, 1500, 0.0);
  EXPECT_DOUBLE_EQ(loss.a, 1484);
}

// Two players: the ranked Elo is elo_update to the bit, whichever way round.
TEST(Elo, RankedOfTwoIsTheOneVersusOneUpdate) {
  for (auto [first, second] : {std::pair{1, 2}, std::pair{2, 1}, std::pair{1, 1}}) {
    auto ranked = elo_ranked({1520, 1433}, {first, second});
    auto pair = elo_update(1520, 1433, pair_score(first, second));
    EXPECT_EQ(ranked[0], pair.a);
    EXPECT_EQ(ranked[1], pair.b);
  }
}

// Three at 1500 ranked 1, 2, 3: each pair a game at K / 2 = 16 with expectation 1/2: the first
// +8 +8, the second +8 -8, the third -8 -8.
TEST(Elo, RankedOfThreeByHand) {
  auto r = elo_ranked({1500, 1500, 1500}, {1, 2, 3});
  EXPECT_DOUBLE_EQ(r[0], 1516);
  EXPECT_DOUBLE_EQ(r[1], 1500);
  EXPECT_DOUBLE_EQ(r[2], 1484);
  EXPECT_THROW(elo_ranked({1500}, {1}), std::invalid_argument);
}

}  // namespace
}  // namespace olympics::selfplay
