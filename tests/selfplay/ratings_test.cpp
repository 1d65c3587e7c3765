// Rating updates against values computed by hand (and matching OpenSkill's published example:
// a 1v1 between two new players gives the winner mu 27.635, sigma 8.0655).
#include "ratings.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace olympics::selfplay
