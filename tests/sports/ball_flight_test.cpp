// The flown ball: official bounce tests, and no tunnelling through the net, the table or the
// ground at the sports' top speeds.
#include "equipment/ball_flight.h"

#include <gtest/gtest.h>

#include <random>

#include "racket/ball_launcher.h"
#include "racket/racket_game.h"

namespace olympics::sports::racket {
namespace {

// Drops the ball (its bottom at `drop`) and returns the rebound height of its bottom.
double rebound(const equipment::BallSpec& spec, double drop) {
  equipment::BallFlight ball(spec, spec.restitution, spec.friction);
  ball.set_state({0, 0, drop + spec.radius}, {0, 0, 0});
  std::vector<equipment::BallContact> contacts;
  bool bounced = false;
  double top = 0;
  for (int i = 0; i < 120 * 5; ++i) {
    ball.step(1.0 / 120, {}, {}, contacts);
    bounced |= !contacts.empty();
    if (bounced) top = std::max(top, ball.position().z() - spec.radius);
    if (bounced && ball.velocity().z() < 0) break;
  }
  return top;
}

TEST(BallFlight, OfficialBounceTestsComeOutInRange) {
  const double tennis = rebound(equipment::tennis_ball(), 2.54);
  EXPECT_GE(tennis, 1.35);
  EXPECT_LE(tennis, 1.47);
  const double table = rebound(equipment::table_tennis_ball(), 0.305);
  EXPECT_GE(table, 0.24);
  EXPECT_LE(table, 0.26);
}

TEST(BallFlight, FastBallsNeverPassThroughNetTableOrGround) {
  std::mt19937_64 rng(5);
  for (const RacketGame& game : {tennis_game(1.0), table_tennis_game()}) {
    const auto arena = game.arena();
    const double top = game.on_table ? 30 : 70;
    std::uniform_real_distribution<double> speed(5, top), y(-0.5, 0.5);
    for (int i = 0; i < 2000; ++i) {
      // Straight at the net's middle from 0.3 m away, low enough to hit it.
      equipment::BallFlight ball(game.ball, game.ball.restitution, game.ball.friction);
      const double z = game.surface_height + 0.5 * (game.net_height - game.surface_height);
      ball.set_state({-0.3, y(rng), z}, {speed(rng), 0, 0});
      std::vector<equipment::BallContact> contacts;
      for (int s = 0; s < 60; ++s) ball.step(1.0 / 120, arena, {}, contacts);
      ASSERT_LT(ball.position().x(), 0) << game.sport << " ball went through the net";
      ASSERT_FALSE(contacts.empty());
      EXPECT_EQ(contacts.front().id, kNet);
    }
    if (!game.on_table) continue;
    for (int i = 0; i < 2000; ++i) {  // straight down onto the table, up to 30 m/s
      equipment::BallFlight ball(game.ball, game.ball.restitution, game.ball.friction);
      ball.set_state({0.5, 0, 1.0}, {0, 0, -speed(rng)});
      std::vector<equipment::BallContact> contacts;
      for (int s = 0; s < 10; ++s) ball.step(1.0 / 120, arena, {}, contacts);
      ASSERT_FALSE(contacts.empty());
      EXPECT_EQ(contacts.front().id, kTable);
      EXPECT_GT(ball.position().z(), game.surface_height) << "through the table";
    }
  }
}

TEST(BallLauncher, AimedBallsLandOnTheirPointAndClearTheNet) {
  std::mt19937_64 rng(11);
  for (const RacketGame& game : {tennis_game(1.0), table_tennis_game()}) {
    for (int i = 0; i < 50; ++i) {
      const Launch launch = ball_return_launch(game, 0, rng);
      equipment::BallFlight ball(game.ball, game.ball.restitution, game.ball.friction);
      ball.set_state(launch.position, launch.velocity);
      std::vector<equipment::BallContact> contacts;
      const auto arena = game.arena();
      while (contacts.empty()) ball.step(1.0 / 120, arena, {}, contacts);
      const auto& first = contacts.front();
      EXPECT_NE(first.id, kNet) << game.sport;
      EXPECT_TRUE(game.in_half(0, first.centre.x(), first.centre.y(), false)) << game.sport;
      EXPECT_NEAR(first.centre.x(), launch.landing.x(), 0.05) << game.sport;
      EXPECT_NEAR(first.centre.y(), launch.landing.y(), 0.05) << game.sport;
    }
  }
}

}  // namespace
}  // namespace olympics::sports::racket
