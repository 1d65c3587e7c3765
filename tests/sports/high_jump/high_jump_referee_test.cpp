// The high-jump referee by sequences of steps (positions from the bar's centre on the ground),
// and the seed's eq. 1 by hand.
#include "high_jump/high_jump_referee.h"

#include <gtest/gtest.h>

#include "high_jump/high_jump_rewards.h"

namespace olympics::sports::high_jump {
namespace {

HighJumpRules official() {
  HighJumpRules r;
  r.official = true;
  r.attempt_s = 60;
  return r;
}

BarStep at(double t, const Eigen::Vector3d& prev, const Eigen::Vector3d& root) {
  BarStep s;
  s.t = t;
  s.bar_height = 1.0;
  s.root_prev = prev;
  s.root = root;
  s.min_body_x = root.x() - 0.5;
  return s;
}

TEST(HighJumpReferee, OverTheBarAndDownOnTheMatWithTheBarUpIsAClearance) {
  HighJumpReferee ref(official());
  EXPECT_FALSE(ref.step(at(1.0, {-0.3, 0, 1.2}, {-0.1, 0, 1.3})));
  EXPECT_FALSE(ref.step(at(1.1, {-0.1, 0, 1.3}, {0.1, 0, 1.3})));  // the root over, above 1.0
  EXPECT_TRUE(ref.over());
  BarStep landing = at(1.4, {0.5, 0, 0.9}, {0.6, 0, 0.8});
  landing.touched_beyond = true;  // the back on the mat while the legs are still behind the plane
  EXPECT_FALSE(ref.step(landing));
  landing.t = 2.95;
  const auto d = ref.step(landing);
  ASSERT_TRUE(d);
  EXPECT_TRUE(d->cleared);
}

TEST(HighJumpReferee, TheBarKnockedOffIsAFailureEvenAfterGoingOver) {
  HighJumpReferee ref(official());
  ref.step(at(1.1, {-0.1, 0, 1.3}, {0.1, 0, 1.3}));
  BarStep knocked = at(1.3, {0.4, 0, 1.0}, {0.5, 0, 0.9});
  knocked.bar_in_place = false;  // a trailing heel took it
  const auto d = ref.step(knocked);
  ASSERT_TRUE(d);
  EXPECT_FALSE(d->cleared);
  EXPECT_EQ(d->reason, "bar_dislodged");
}

TEST(HighJumpReferee, TouchingBeyondThePlaneBeforeGoingOverIsAFailure) {
  HighJumpReferee under(official());
  // the root crosses the plane below the bar (running under it)
  EXPECT_FALSE(under.step(at(1.0, {-0.1, 0, 0.9}, {0.1, 0, 0.9})));
  EXPECT_FALSE(under.over());
  BarStep touch = at(1.1, {0.1, 0, 0.9}, {0.2, 0, 0.9});
  touch.touched_beyond = true;
  EXPECT_EQ(under.step(touch)->reason, "touched_beyond");
  HighJumpReferee around(official());  // above the bar's height but outside the uprights
  around.step(at(1.0, {-0.1, 2.5, 1.3}, {0.1, 2.5, 1.3}));
  EXPECT_FALSE(around.over());
}

TEST(HighJumpReferee, TheTimeAndAFallBeforeTheJumpAreFailures) {
  HighJumpReferee slow(official());
  EXPECT_EQ(slow.step(at(60.1, {-5, 0, 0.9}, {-5, 0, 0.9}))->reason, "time");
  HighJumpReferee fallen(official());
  BarStep s = at(3, {-5, 0, 0.3}, {-5, 0, 0.3});
  s.down = true;
  EXPECT_EQ(fallen.step(s)->reason, "fell");
}

TEST(HighJumpReferee, LeavingTheFanShapedRunUpBeforeTheJumpIsAFailure) {
  // The run-up: the half disc of 25 m round the bar's centre, on the approach side (x < 0).
  HighJumpReferee inside(official());
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(-20, -6, 0.9), Eigen::Vector3d(-0.5, 24.9, 0.9),
                                   Eigen::Vector3d(-17.6, 17.6, 0.9), Eigen::Vector3d(2, 0, 0.9)})
    EXPECT_FALSE(inside.step(at(1, p, p))) << p.transpose() << " is in the run-up";
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(-25.1, 0, 0.9), Eigen::Vector3d(-0.5, 25.1, 0.9),
                                   Eigen::Vector3d(-17.8, -17.8, 0.9)}) {
    HighJumpReferee out(official());
    const auto d = out.step(at(1, p, p));
    ASSERT_TRUE(d) << p.transpose() << " is outside the run-up";
    EXPECT_FALSE(d->cleared);
    EXPECT_EQ(d->reason, "left_area");
  }
  HighJumpRules wide = official();
  wide.runup_radius = 40;
  const Eigen::Vector3d far(-30, 0, 0.9);
  EXPECT_FALSE(HighJumpReferee(wide).step(at(1, far, far))) << "a 40 m fan holds 30 m out";
}

TEST(HighJumpReferee, PaperClearsWhenEveryBodyIsPastThePlane) {
  HighJumpReferee ref(HighJumpRules{});
  BarStep s = at(1, {-0.2, 0, 1.3}, {0.5, 0, 1.3});
  s.min_body_x = 0.09;
  EXPECT_FALSE(ref.step(s));
  s.root_prev = s.root;  // the root crossed above the bar on the step before
  s.min_body_x = 0.11;
  EXPECT_TRUE(ref.step(s)->cleared);
  HighJumpReferee strayed(HighJumpRules{});
  EXPECT_EQ(strayed.step(at(1, {-20, -6, 0.9}, {-20, -8.1, 0.9}))->reason, "left_area");
}

TEST(HighJumpReferee, PaperWalkingUnderAHighBarIsNoClearance) {
  HighJumpRules rules;
  BarStep s = at(1, {-0.2, 0, 0.9}, {0.3, 0, 0.9});
  s.bar_height = 2.0;  // the seed's highest bar, above a walking root
  s.min_body_x = 0.11;
  const auto call = HighJumpReferee(rules).step(s);
  ASSERT_TRUE(call);
  EXPECT_FALSE(call->cleared);
  EXPECT_EQ(call->reason, "under_the_bar");
}

// Eq. 1 by hand: R = r_p away from the bar, r_p + r_h within 0.5 m of its plane (x = 20).
TEST(HighJumpRewards, EachTermIsTheSeedsOnAHandComputedState) {
  const Eigen::Vector3d goal{22, 6, 1};
  // 3-4-5: from (18, 6, 4) to goal is sqrt(16 + 9) = 5; from (18.8, 6, 3.4) it is 4
  auto t = high_jump_reward_terms({18, 6, 4}, {18.8, 6, 3.4}, goal, 20.0);
  EXPECT_NEAR(t[0], 1.0, 1e-6);
  EXPECT_EQ(t[1], 0.0f) << "x = 18.8: no height term";
  t = high_jump_reward_terms({19.6, 6, 1.4}, {19.7, 6, 1.5}, goal, 20.0);
  // |(19.6, 6, 1.4) - G| = sqrt(2.4^2 + 0.4^2); |(19.7, 6, 1.5) - G| = sqrt(2.3^2 + 0.5^2)
  EXPECT_NEAR(t[0], std::sqrt(2.4 * 2.4 + 0.4 * 0.4) - std::sqrt(2.3 * 2.3 + 0.5 * 0.5), 1e-6);
  EXPECT_NEAR(t[1], 1.5, 1e-6) << "x = 19.7: r_h = the root's height";
  t = high_jump_reward_terms({20.6, 6, 1}, {20.5, 6, 1}, goal, 20.0);
  EXPECT_EQ(t[0], 0.0f) << "moving away: clamped";
  EXPECT_NEAR(t[1], 1.0, 1e-6) << "x = 20.5 is still within";
}

}  // namespace
}  // namespace olympics::sports::high_jump
