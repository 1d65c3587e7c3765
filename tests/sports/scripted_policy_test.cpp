// The scripted baseline's legs and its play: it walks where it is sent without falling, and in
// ball-return episodes it moves toward where the ball will come.
#include <gtest/gtest.h>

#include <cmath>

#include "core/control_rate.h"
#include "core/humanoid_assets.h"
#include "core/humanoid_scene.h"
#include "core/rotation.h"
#include "core/self_observation.h"
#include "racket/racket_equipment.h"
#include "racket_match_harness.h"
#include "registry.h"
#include "scripted_racket.h"
#include "scripted_racket_play.h"
#include "smpl_observation.h"
#include "step_controller.h"

namespace olympics::client {
namespace {

struct Walk {
  double error_m = 0;  // distance to the target at the end
  double min_root_height = 10;
};

// A racket-carrying humanoid sent to a fixed ground point (world frame) for `seconds`.
Walk walk_to(const Eigen::Vector2d& target, double seconds) {
  core::ModelSpec spec = core::load_humanoid(core::HumanoidKind::Smpl);
  sports::equipment::attach_equipment(spec, sports::racket::tennis_racket());
  core::HumanoidScene scene;
  scene.add_humanoid(spec, {{0, 0, 0}, 0});
  StepController legs({}, core::kControlDt);
  std::vector<float> obs(358), act(69);
  Walk w;
  Eigen::Vector3d root = Eigen::Vector3d::Zero();
  for (int tick = 0; tick < seconds * 30; ++tick) {
    const auto bodies = scene.humanoid(0).body_states();
    core::write_self_observation(bodies, obs);
    root = bodies[0].position;
    w.min_root_height = std::min(w.min_root_height, root.z());
    const Eigen::Vector3d to_target =
        core::inverse_heading(bodies[0].orientation) *
        Eigen::Vector3d(target.x() - root.x(), target.y() - root.y(), 0);
    std::fill(act.begin(), act.end(), 0.0f);
    legs.act(obs, to_target.head<2>(), -core::heading_angle(bodies[0].orientation), act);
    scene.set_action(0, act);
    scene.tick();
  }
  w.error_m = (root.head<2>() - target).norm();
  return w;
}

TEST(StepController, WalksToPointsAroundItWithoutFalling) {
  for (const Eigen::Vector2d& target :
       {Eigen::Vector2d(1, 0), Eigen::Vector2d(-1, 0), Eigen::Vector2d(0, 1),
        Eigen::Vector2d(0, -1), Eigen::Vector2d(1.5, 1.5)}) {
    const Walk w = walk_to(target, 5.0);
    EXPECT_GT(w.min_root_height, 0.6) << "fell walking to " << target.transpose();
    EXPECT_LT(w.error_m, 0.5) << "walking to " << target.transpose();
  }
}

TEST(StepController, StandsStillWhenAlreadyThere) {
  const Walk w = walk_to({0, 0}, 3.0);
  EXPECT_GT(w.min_root_height, 0.8);
  EXPECT_LT(w.error_m, 0.1);
}

TEST(StepController, TargetReachedMidStepGivesFiniteActions) {
  core::ModelSpec spec = core::load_humanoid(core::HumanoidKind::Smpl);
  core::HumanoidScene scene;
  scene.add_humanoid(spec);
  std::vector<float> obs(358), act(69, 0.0f);
  core::write_self_observation(scene.humanoid(0).body_states(), obs);
  StepController legs({}, core::kControlDt);
  legs.act(obs, {1, 0}, 0, act);
  ASSERT_TRUE(legs.stepping());
  legs.act(obs, {0, 0}, 0, act);
  for (float x : act) EXPECT_TRUE(std::isfinite(x));
}

// Ball-return episodes: when the ball will pass far from where the racket meets it, but within
// what the legs can walk in time, the player has moved toward the side it comes to by the time it
// arrives; a ball further than that (2.3 m or more sideways here) it lets go, standing (issue 29,
// tennis falls: running after those, the player fell; seeds 1-20: 3 balls 0.6-2.2 m off, moved
// toward 3; 5 balls 2.3-5.6 m off, moved 0.04-0.26 m).
TEST(ScriptedRacketPolicy, MovesTowardTheComingBall) {
  int far_balls = 0, moved_toward = 0, too_far = 0, stood = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    auto match = sports::sport_or_throw("tennis").create({"ball_return", seed, 30.0, {}});
    const auto layout = ObservationLayout::from_blocks(match->layout().observation);
    const int kCourtY = layout.offset("court_position", "y");
    const int kBallX = layout.offset("ball_position", "position"), kBallY = kBallX + 1;
    ScriptedRacketPolicy policy;
    policy.start({"tennis", "ball_return", core::kControlDt, layout, 69});
    std::vector<float> obs(match->obs_size()), act(69);
    match->observe(0, obs);
    const double start_y = obs[kCourtY];
    while (!match->outcome().match_over) {
      match->observe(0, obs);
      if (obs[kBallX] < 0.5) break;  // the ball has reached the player
      policy.act(obs, act);
      match->step({std::span<const float>(act)});
    }
    if (match->outcome().match_over) continue;
    // Court y of the ball here, and where the player should stand: the ball 1.05 m to its right.
    const double ball_court_y = obs[kCourtY] + obs[kBallY];
    const double wanted = ball_court_y + 1.05 - start_y;
    if (std::abs(wanted) < 0.6) continue;
    const double moved = obs[kCourtY] - start_y;
    if (std::abs(wanted) > 2.3) {
      ++too_far;
      if (std::abs(moved) < 0.3) ++stood;
      continue;
    }
    ++far_balls;
    if (moved * wanted > 0 && std::abs(moved) > 0.15) ++moved_toward;
  }
  std::printf("far balls %d, moved toward %d; too far %d, stood %d\n", far_balls, moved_toward,
              too_far, stood);
  ASSERT_GE(far_balls, 3);
  EXPECT_GE(moved_toward, 0.8 * far_balls) << moved_toward << " of " << far_balls;
  ASSERT_GE(too_far, 3);
  EXPECT_EQ(stood, too_far);
}

// The scripted table-tennis player returns fed balls onto the other half: of the first balls of
// 20 ball-return episodes (the same 20 feeds every run) it returns several in. Measured rate on
// unseen seeds: olympics-bench racket (about a third).
TEST(ScriptedRacketPolicy, ReturnsFedBallsOntoTheOtherHalf) {
  int returned = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    ScriptedRacketPlay play("table_tennis", {"ball_return", seed, 10.0, {}});
    bool first_ball_over = false;
    while (!play.over() && !first_ball_over) {
      for (const auto& ev : play.tick()) {
        const std::string call = ev.value("call", "");
        if (call == "return_in") ++returned;
        if (call == "return_in" || call == "point") first_ball_over = true;
      }
    }
  }
  std::printf("first balls returned in: %d of 20\n", returned);
  EXPECT_GE(returned, 4);
}

// Table-tennis ball return, whole episodes (every ball fed until one is lost) of seeds 201-300,
// the last third of the tuning seeds of issue 29's sixth and seventh rounds: the player meets
// balls 0.25 m right of its line, not at the forehand's sweet spot 0.45 m right (sixth round),
// and draws the backswing within the reach it met the ball within, the trunk's lean included
// (seventh round), and returns more of them in. Measured: 78 of 178 balls (43.8%); the backswing
// within the arm's own reach (the sixth round), 66 of 166 (39.8%); at the sweet spot, 41 of 141
// (29.1%). (All of seeds 1-300: 41.5% / 37.5% / 31.5%; unseen seeds: docs/racket-sports.md.)
TEST(ScriptedRacketPolicy, ReturnsMoreFedBallsMetNearTheBodyLine) {
  int fed = 0, returned = 0;
  for (std::uint64_t seed = 201; seed <= 300; ++seed) {
    ScriptedRacketPlay play("table_tennis", {"ball_return", seed, 60.0, {}});
    while (!play.over())
      for (const auto& ev : play.tick()) {
        const std::string call = ev.value("call", "");
        if (call == "return_in") ++returned, ++fed;
        if (call == "point") ++fed;
      }
  }
  std::printf("returned in %d of %d fed balls\n", returned, fed);
  ASSERT_GE(fed, 100);
  EXPECT_GE(returned, 0.42 * fed) << "the backswing within the arm's own reach: 66 of 166; "
                                     "met at the sweet spot: 41 of 141";
}

// The feed comes at the fed player's body line, 0.25 m left of where it meets balls: the player
// sidesteps left as it comes, so that the ball passes on the racket side. Over the first balls
// of ball-return seeds 1-40, where the ball is as it comes level with the sweet spot (0.45 m
// ahead of the root): on average at least 0.05 m right of the root (for a player standing still
// about 0: the feed is aimed within 0.11 m of its line; measured 0.069 m), and at most one of the
// 40 falls (measured 1). (Meeting balls at the sweet spot, 0.45 m right, before issue 29's sixth
// round, the bar was 0.16 m: 0.185 m with these side steps, 0.143 m with the walker's default
// side gait.) Ball return, not 1v1: since 1v1's legs start each point afresh, the first step by
// the trailing foot, the fed player meets the feed about where it stands (0.017 m right at the
// first feeds of 1v1 seeds 1-40, 0.082 m before) and loses fewer points on it
// (TableTennisLegsStartEachPointAfreshAndMeetTheFeedNearTheMark).
TEST(ScriptedRacketPolicy, SidestepsSoTheFeedPassesOnTheRacketSide) {
  int feeds = 0, falls = 0;
  double side_sum = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    ScriptedRacketPlay play("table_tennis", {"ball_return", seed, 10.0, {}});
    const int kBall = play.layout.offset("ball_position", "position");
    const int kComing = play.layout.offset("rally", "coming");
    bool seen = false, point_over = false;
    while (!play.over() && !point_over) {
      const auto events = play.tick([&](int s) {
        const float* ball = &play.obs[s][kBall];  // heading frame of this player's root
        if (!seen && play.obs[s][kComing] > 0.5f && ball[0] < 0.45f) {
          seen = true, ++feeds;
          side_sum += ball[1];
        }
      });
      for (const auto& ev : events) {
        const std::string call = ev.value("call", "");
        if (call == "fall") ++falls;
        if (call == "point" || call == "return_in") point_over = true;  // the first ball
      }
    }
  }
  std::printf("feeds %d, ball at y %.3f m from the root (left +), falls %d\n", feeds,
              side_sum / feeds, falls);
  // A feed struck before it comes level with the sweet spot is not counted: since the racket
  // waits at the ready point until the backswing (HoldsTheRacketOffTheBodyLineWhileStepping), 7
  // of the 40 were (before, 3); met 0.25 m right of the root (sixth round), none.
  ASSERT_GE(feeds, 30);
  EXPECT_LE(side_sum / feeds, -0.05) << "standing still: about 0";
  EXPECT_LE(falls, 1);
}

// While the legs still walk to where a table-tennis ball will be met (more than 0.6 s before
// it), the racket waits at the ready point, out to the right, rather than drawn back: a backswing
// drawn straight back for a ball on the body line holds the arm across the trunk, and stepping so
// topples the player. Over the first two points of 1v1 seeds 1-20, the share of such ticks with
// the racket hand within 0.25 m of the root's vertical axis.
TEST(ScriptedRacketPolicy, HoldsTheRacketOffTheBodyLineWhileStepping) {
  int ticks = 0, near_axis = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    ScriptedRacketPlay play("table_tennis", {"1v1", seed, 0.0, {}});
    int points = 0;
    while (!play.over() && points < 2) {
      const auto events = play.tick([&](int s) {
        const auto& stroke = play.players[s].stroke();
        if (stroke && stroke->time_to_hit > 0.6) {
          ++ticks;
          near_axis += smpl::body_position(play.obs[s], smpl::kRHand).head<2>().norm() < 0.25;
        }
      });
      for (const auto& ev : events) points += ev.value("call", "") == "point";
    }
  }
  std::printf("ticks stepping to a planned stroke %d, racket hand near the body's axis %d\n", ticks,
              near_axis);
  ASSERT_GE(ticks, 100);
  EXPECT_LE(near_axis, 0.05 * ticks);
}

// A table-tennis ball the player swung at and missed (its committed contact passed, the ball
// still coming) is let go: no later point of its path, behind the player, is planned and walked
// to. Chasing such balls, at 1-1.5 m from a stance with 0.1-0.2 s left, was where two of the six
// falls traced on 1v1 tuning seeds 1-20 came (issue 29, ninth round; docs/racket-sports.md). Over
// the first 30 points of 1v1 seeds 1-5: strokes planned again for a ball already swung past.
TEST(ScriptedRacketPolicy, LetsGoOfABallItSwungAtAndMissed) {
  int swung_past = 0, chased = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    ScriptedRacketPlay play("table_tennis", {"1v1", seed, 0.0, {}});
    const int kComing = play.layout.offset("rally", "coming");
    const int kStruck = play.layout.offset("rally", "struck");
    std::vector<bool> past(play.players.size(), false);  // swung past the ball now coming
    int points = 0;
    while (!play.over() && points < 30) {
      const auto events = play.tick([&](int s) {
        const bool coming = play.obs[s][kComing] > 0.5f && play.obs[s][kStruck] < 0.5f;
        const auto& stroke = play.players[s].stroke();
        if (!coming) past[s] = false;
        if (coming && stroke && stroke->reachable && stroke->time_to_hit < -0.1 && !past[s])
          past[s] = true, ++swung_past;
        if (coming && past[s] && stroke && stroke->time_to_hit > 0) ++chased, past[s] = false;
      });
      for (const auto& ev : events)
        if (ev.value("call", "") == "point") {
          ++points;
          std::fill(past.begin(), past.end(), false);
        }
    }
  }
  std::printf("balls swung past %d, chased after %d\n", swung_past, chased);
  ASSERT_GE(swung_past, 10);
  EXPECT_EQ(chased, 0);
}

// A point that ended while a player's stroke was committed (its ball on the body, say) left that
// stroke running into the next point: it counted down against the new feed, was let go as missed,
// and the fed player planned nothing for the feed, which then struck its body (issue 29, short
// points: 46 of the 67 feeds on a body in 1v1 tuning seeds 1-8). Every feed now gets a stroke
// planned while it comes (1v1 seeds 1-4, a game each: 6 of 35 feeds had none in seeds 1-2 before;
// Play::forget_stroke_at_new_point).
TEST(ScriptedRacketPolicy, PlansAStrokeForEveryFeed) {
  int feeds = 0, unplanned = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    ScriptedRacketPlay play("table_tennis", {"1v1", seed, 0.0, {}});
    const int kComing = play.layout.offset("rally", "coming");
    std::vector<bool> fed(play.players.size(), false), planned(fed);
    bool feed_coming = true;  // the point's first ball, not struck yet
    while (!play.over()) {
      const auto events = play.tick([&](int s) {
        if (!feed_coming || play.obs[s][kComing] < 0.5f) return;
        fed[s] = true;
        const auto& stroke = play.players[s].stroke();
        if (stroke && stroke->time_to_hit > 0.3) planned[s] = true;
      });
      for (const auto& ev : events) {
        const std::string call = ev.value("call", "");
        if (call == "hit") feed_coming = false;
        if (call != "point") continue;
        feed_coming = true;
        for (size_t s = 0; s < fed.size(); ++s) feeds += fed[s], unplanned += fed[s] && !planned[s];
        std::fill(fed.begin(), fed.end(), false), std::fill(planned.begin(), planned.end(), false);
      }
    }
  }
  std::printf("%d feeds, %d with no stroke planned\n", feeds, unplanned);
  ASSERT_GE(feeds, 60);
  EXPECT_EQ(unplanned, 0);
}

// The table-tennis arm's face came short, to the right of the ball, and the missed ball ran on
// into the trunk: the face is asked for 4 cm left of where the plan meets the ball, but only where
// such a ball meets the trunk, between the racket shoulder's line and the root's. Asked for
// everywhere it took the arm further across the body, and 1v1 falls rose (issue 29,
// docs/racket-sports.md, the face aimed left between the shoulder and the root).
TEST(ScriptedRacketPolicy, AimsTheFaceLeftOnlyBetweenTheShoulderAndTheRoot) {
  namespace rp = olympics::client::racket_play;
  const rp::Play play = rp::table_play();
  const Eigen::Vector3d shoulder(0, -0.18, 0.4), left(0, 0.04, 0);
  auto bias_at = [&](double y) {
    return rp::face_aim_bias(play, Eigen::Vector3d(0.45, y, 0.15), shoulder);
  };
  EXPECT_TRUE(bias_at(-0.1).isApprox(left)) << "in front of the trunk, right of the root";
  EXPECT_TRUE(bias_at(-0.25).isZero()) << "right of the shoulder: a miss passes beside the body";
  EXPECT_TRUE(bias_at(0.05).isZero()) << "across the body";
  EXPECT_TRUE(
      rp::face_aim_bias(rp::tennis_play(), Eigen::Vector3d(0.45, -0.1, 0.15), shoulder).isZero())
      << "tennis untouched";
}

// Two scripted table-tennis players finish a game to 11 by score, with rallies in it.
TEST(ScriptedRacketPolicy, OneVsOneEndsByScoreWithRallies) {
  ScriptedRacketPlay play("table_tennis", {"1v1", 1, 0.0, {}});
  const auto& match = play.match;
  int strokes = 0, rallies = 0;  // rallies: points with strokes by both sides
  while (!play.over()) {
    for (const auto& ev : play.tick()) {
      const std::string call = ev.value("call", "");
      if (call == "hit") ++strokes;
      if (call == "point") rallies += strokes >= 2, strokes = 0;
    }
  }
  EXPECT_NE(match->outcome().reason, "time_limit");
  EXPECT_GE(rallies, 3) << "points with strokes by both sides";
}

// Between balls the table-tennis player waits 1.8 m behind the net, 0.43 m behind the table's end,
// not at 2 m where each point starts (issue 29, the rally round): a short return, 0.3 m past the
// net, bounces twice on the table before a player 2 m back gets to it, and more rallies last
// (1v1 tuning seeds 1-20: strokes per point 1.18 -> 1.51; docs/racket-sports.md). In 1v1
// matches of seeds 1-4 (whole matches, about 50 s here), as the other side strikes a rally ball
// (a point's second stroke or later) its receiver stands nearer the net on average, and more
// points reach it: measured 61 rally balls, the receiver at x -1.407 (court frame; waiting 2 m
// back: 40, -1.478; players stand where they struck their last ball until they walk home).
TEST(ScriptedRacketPolicy, WaitsNearerTheTableEndBetweenBalls) {
  double sum_x = 0;
  int rally_balls = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    ScriptedRacketPlay play("table_tennis", {"1v1", seed, 0.0, {}});
    const int kX = play.layout.offset("court_position", "x");
    int strokes = 0;
    while (!play.over()) {
      for (const auto& ev : play.tick()) {
        const std::string call = ev.value("call", "");
        if (call == "point") strokes = 0;
        if (call != "hit") continue;
        // A rally ball (not the feed's return): where its receiver stands as it is struck.
        const int striker = ev.value("slot", -1);
        if (++strokes >= 2 && striker >= 0) sum_x += play.obs[1 - striker][kX], ++rally_balls;
      }
    }
  }
  const double mean_x = sum_x / std::max(1, rally_balls);
  std::printf("%d rally balls, the receiver at a mean x %.3f\n", rally_balls, mean_x);
  EXPECT_GE(rally_balls, 50) << "waiting 2 m back: 40";
  EXPECT_GT(mean_x, -1.44) << "waiting 2 m back: -1.478";
  // ...and, standing 0.6 s after its own stroke before it walks home (Play::home_after_s; issue
  // 29, the recovery round), nearer still: -1.348.
  EXPECT_GT(mean_x, -1.38) << "walking home 0.4 s after the stroke: -1.407";
}

// A table-tennis ball met across the body (left of the racket shoulder's line) is struck with the
// paddle's front face, the side the forehand uses, the arm reaching across: with either side
// allowed, the inverse kinematics turned the wrist over to the back face there (a backhand grip),
// the posture solved exactly, but the arm driven toward it left the face 10-18 cm right of and
// below the ball, which ran on into the trunk (issue 29, the backhand round:
// docs/racket-sports.md). Over 1v1 seeds 1-3: the face's side at the planned contact of every
// stroke within reach met left of the shoulder's line, and the points that ended without a stroke.
TEST(ScriptedRacketPolicy, MeetsBallsAcrossTheBodyWithThePaddlesFrontFace) {
  int across = 0, front = 0, points = 0, no_stroke = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    ScriptedRacketPlay play("table_tennis", {"1v1", seed, 0.0, {}});
    const int kX = play.layout.offset("court_position", "x");
    const int kY = play.layout.offset("court_position", "y");
    const int kCos = play.layout.offset("court_heading", "cos");
    const int kSin = play.layout.offset("court_heading", "sin");
    std::vector<double> last_time_to_hit(play.players.size(), 9);
    int strokes = 0;
    while (!play.over()) {
      const auto events = play.tick([&](int s) {
        const auto& o = play.obs[s];
        const auto& stroke = play.players[s].stroke();
        const double before = last_time_to_hit[s];
        last_time_to_hit[s] = stroke ? stroke->time_to_hit : 9;
        // The tick the planned contact comes, for a stroke within reach.
        if (!stroke || !stroke->reachable || before <= 0 || stroke->time_to_hit > 0) return;
        control::CourtFrame court;
        court.root = {o[kX], o[kY], smpl::root_height(o)};
        court.yaw = std::atan2(o[kSin], o[kCos]);
        const Eigen::Vector3d met = court.to_heading_point(stroke->ball_at);
        if (met.y() < smpl::body_position(o, smpl::kRShoulder).y()) return;
        ++across;
        // The face's normal is the hand's z axis (sports/equipment/equipment.h).
        front += smpl::body_rotation(o, smpl::kRHand)
                     .col(2)
                     .dot(court.to_heading_vector(stroke->normal)) > 0;
      });
      for (const auto& ev : events) {
        const std::string call = ev.value("call", "");
        if (call == "hit") ++strokes;
        if (call == "point") ++points, no_stroke += strokes == 0, strokes = 0;
      }
    }
  }
  std::printf("strokes met across the body %d, with the front face %d; points %d, no stroke %d\n",
              across, front, points, no_stroke);
  ASSERT_GE(across, 15);
  EXPECT_GE(front, 0.9 * across) << "either face allowed: 10 of 22";
  EXPECT_LE(no_stroke, 0.1 * points) << "either face allowed: 8 of 49";
}

// Table-tennis returns are aimed 0.45 m past the net, not 0.6 (issue 29, the passing balls): a
// receiver still at the table's end, where it met its last short ball, could not meet a ball that
// landed 0.6-1.0 m past the net in front of it (no contact point in front of the body clears the
// table there), and the ball passed it; balls landing 0.4-0.6 m past the net were met. Over 1v1
// seeds 41-46 (tuning seeds of that round), points that ended with the ball passing its receiver:
// measured 9 of 119 (aimed 0.6 m past the net: 34 of 111).
TEST(ScriptedRacketPolicy, FewerTableTennisBallsPassTheReceiver) {
  int points = 0, passed = 0;
  for (std::uint64_t seed = 41; seed <= 46; ++seed) {
    ScriptedRacketPlay play("table_tennis", {"1v1", seed, 0.0, {}});
    while (!play.over()) {
      for (const auto& ev : play.tick()) {
        if (ev.value("call", "") != "point") continue;
        ++points, passed += ev.value("reason", "") == "missed";
      }
    }
  }
  std::printf("%d points, %d ended with the ball passing the receiver\n", points, passed);
  ASSERT_GE(points, 100);
  EXPECT_LT(passed, 0.15 * points) << "aimed 0.6 m past the net: 34 of 111";
}

// At each point of a match both players are put back at their marks, standing. The table-tennis
// legs ran on with the step under way when the last point ended (at 97% of point starts, the
// swing foot yanked up mid-step); started afresh and standing, or stepping at once by the lead
// foot, the fed player's feed stroke went into the net, short or out more often (a body that
// topples forward while standing; a full-speed sidestep to the feed). Now they start afresh,
// stepping at once, the trailing foot first, and the fed player meets the feed about where it
// stands (issue 29, the legs at a point's start; docs/racket-sports.md). Over 1v1 seeds 61-64
// (tuning seeds of that round, the bench's format): no step runs on from the point before, and
// points that end with the feed's stroke in the net, short or out: measured 9 of 200 (main: 34
// of 188, a step run on at 313 of 368 point starts; afresh, stepping at once by the lead foot:
// 105 of 320 points on seeds 61-66).
TEST(ScriptedRacketPolicy, TableTennisLegsStartEachPointAfreshAndMeetTheFeedNearTheMark) {
  int starts = 0, steps_run_on = 0, points = 0, feed_lost = 0;
  for (std::uint64_t seed = 61; seed <= 64; ++seed) {
    ScriptedRacketPlay play("table_tennis",
                            {"1v1", seed, 0.0, {{"games_to_win", 2}, {"points_per_game", 11}}});
    bool new_point = false;
    while (!play.over()) {
      const auto events = play.tick([&](int slot) {
        if (!new_point) return;
        ++starts;
        steps_run_on += play.legs_step_run_on(slot);
      });
      new_point = false;
      for (const auto& ev : events) {
        if (ev.value("call", "") != "point") continue;
        new_point = true, ++points;
        const std::string why = ev.value("reason", "");
        feed_lost +=
            ev.value("strokes", 0) == 1 && (why == "net" || why == "not_over" || why == "out");
      }
    }
  }
  std::printf("point starts %d, steps run on %d; points %d, lost on the feed's stroke %d\n", starts,
              steps_run_on, points, feed_lost);
  ASSERT_GE(points, 150);
  EXPECT_EQ(steps_run_on, 0) << "main: most point starts";
  EXPECT_LT(feed_lost, 0.09 * points) << "main: 34 of 188";
}

}  // namespace
}  // namespace olympics::client
