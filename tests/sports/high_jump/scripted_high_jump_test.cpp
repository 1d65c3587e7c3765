// The scripted high jumper (clients/agent/scripted_high_jump.h), played in process: on seeds no
// search or tuning saw it walks from the event's own start and clears a 0.5 m bar, paper and
// official; the search that found its jump and a probe that prints attempts (which body first
// touched the bar, how far the bar moved).
#include "scripted_high_jump.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>

#include "../athletics/cross_entropy_search.h"
#include "high_jump/high_jump_match.h"
#include "high_jump/high_jump_sport.h"
#include "registry.h"

namespace olympics::sports::high_jump {
namespace {

struct Attempt {
  nlohmann::json decision;  // cleared or failure
  double rear_x = -1e9;     // the body origin nearest the run-up, from the bar's plane, then
  Eigen::Vector3d root = Eigen::Vector3d::Zero();  // where the root was at the end, from the bar
  double jump_t = -1;                              // s: when the jump began (-1: never)
  Eigen::Vector3d jump_root = Eigen::Vector3d::Zero();      // the root then, from the bar
  Eigen::Vector3d jump_velocity = Eigen::Vector3d::Zero();  // the root's velocity then
  std::string first_touch;  // the first body seen touching the bar (at a control tick), if any
  double touch_t = -1;      // s: when
  double touch_top = 0;     // m: that body's origin above the bar's top then
  double bar_moved = 0;     // m: the most the bar's middle moved from where it rested
  double top_z = 0;         // m: the highest any body's origin got before the decision
};

// The athlete's first body whose geoms touch the crossbar's, or -1.
int body_touching_bar(const core::Humanoid& h, const Crossbar& bar) {
  dContactGeom contact[4];
  dGeomID bar_geom = dBodyGetFirstGeom(bar.body());
  for (int b = 0; b < h.body_count(); ++b)
    for (dGeomID g = dBodyGetFirstGeom(h.ode_body(b)); g; g = dBodyGetNextGeom(g))
      if (dCollide(g, bar_geom, 4, contact, sizeof(dContactGeom)) > 0) return b;
  return -1;
}

double rearmost_x(const core::Humanoid& h) {
  double rear = 1e9;
  for (int b = 0; b < h.body_count(); ++b) rear = std::min(rear, h.body_state(b).position.x());
  return rear;
}

// One attempt by the scripted jumper. `bar_x` > 0 moves the bar's middle to (bar_x, 0), right
// ahead of the start mark: the search's short approach.
Attempt jump_once(std::uint64_t seed, const client::HighJumpPlan& plan,
                  const nlohmann::json& settings, double bar_x = 0) {
  const auto& sport = dynamic_cast<const HighJumpSport&>(sport_or_throw("high_jump"));
  HighJumpRules rules = sport.rules(settings);
  if (bar_x > 0) rules.bar_x = bar_x, rules.bar_y = 0;
  MatchSettings s{"solo", seed, 0.0, settings};
  s.time_limit_s = rules.attempt_s;
  HighJumpMatch m(rules, sport.modes().at("solo"), sport.layout("solo"), s);
  client::ScriptedHighJumpPolicy jumper(plan);
  jumper.start({"high_jump", "solo", 1.0 / 30,
                client::ObservationLayout::from_blocks(m.layout().observation), m.action_size()});
  std::vector<float> obs(m.obs_size()), act(m.action_size());
  Attempt at;
  const Eigen::Vector3d bar_rest = m.bar(0).position();
  for (int tick = 0; tick < (rules.attempt_s + 1) * 30 && at.decision.is_null(); ++tick) {
    m.observe(0, obs);
    jumper.act(obs, act);
    if (jumper.jumping() && at.jump_t < 0) {
      at.jump_t = tick / 30.0;
      at.jump_root =
          m.athlete(0).body_state(0).position - Eigen::Vector3d(rules.bar_x, rules.bar_y, 0);
      at.jump_velocity = m.athlete(0).body_state(0).linear_velocity;
    }
    if (std::getenv("TRACE") && tick % 15 == 0) {
      const core::BodyState root = m.athlete(0).body_state(0);
      std::printf("  t %.1f root %.2f %.2f %.2f v %.2f %.2f%s\n", tick / 30.0,
                  root.position.x() - rules.bar_x, root.position.y() - rules.bar_y,
                  root.position.z(), root.linear_velocity.x(), root.linear_velocity.y(),
                  jumper.jumping() ? " jumping" : "");
    }
    // The state before the step: where a series goes on, the decided attempt's athlete is
    // already back on its mark after it.
    const Eigen::Vector3d root_before = m.athlete(0).body_state(0).position;
    const double rear_before = rearmost_x(m.athlete(0));
    m.step({std::span<const float>(act)});
    if (at.touch_t < 0) {
      const int b = body_touching_bar(m.athlete(0), m.bar(0));
      if (b >= 0) {
        at.first_touch = m.athlete(0).spec().bodies[b].name;
        at.touch_t = (tick + 1) / 30.0;
        at.touch_top = m.athlete(0).body_state(b).position.z() - m.bar(0).height();
      }
    }
    for (const auto& e : m.outcome().info["events"])
      if (e["call"] == "cleared" || e["call"] == "failure") {
        at.decision = e;
        const bool back_on_mark = !m.outcome().match_over;
        at.rear_x = (back_on_mark ? rear_before : rearmost_x(m.athlete(0))) - rules.bar_x;
        at.root = back_on_mark ? root_before : m.athlete(0).body_state(0).position;
      }
    // Until the decision: a clearance in a series puts the bar up for the next height.
    if (at.decision.is_null()) {
      at.bar_moved = std::max(at.bar_moved, (m.bar(0).position() - bar_rest).norm());
      for (int b = 0; b < m.athlete(0).body_count(); ++b)
        at.top_z = std::max(at.top_z, m.athlete(0).body_state(b).position.z());
    }
  }
  if (at.decision.is_null()) at.root = m.athlete(0).body_state(0).position;
  at.root -= Eigen::Vector3d(rules.bar_x, rules.bar_y, 0);
  return at;
}

// The jumper's plan with the settings a search or probe run names: JUMP="20 numbers" (a
// search's means), the walker's gains (MAX_SPEED, STEP_S, MAX_STEP, LEAD_S, VGAIN, SPM, LIFT,
// LEG, UPRIGHT, SIDE, TURN) and the approach's (LINE, STOP, STILL, ARRIVED, STILL_SPEED, SIDE_M).
client::HighJumpPlan plan_from_env() {
  client::HighJumpPlan plan;
  if (const char* jump = std::getenv("JUMP")) {
    std::vector<double> x(client::control::StandingJump::kParameters);
    std::istringstream in(jump);
    for (double& v : x) in >> v;
    plan.approach.jump = client::control::StandingJump::from(x);
  }
  auto env = [](const char* name, double& value) {
    if (const char* v = std::getenv(name)) value = std::atof(v);
  };
  client::StepGains& walk = plan.approach.walk;
  env("MAX_SPEED", walk.max_speed), env("STEP_S", walk.step_s), env("MAX_STEP", walk.max_step);
  env("LEAD_S", walk.lead_s), env("VGAIN", walk.velocity_gain), env("SPM", walk.speed_per_m);
  env("LIFT", walk.lift), env("LEG", walk.leg_length), env("UPRIGHT", walk.upright_gain);
  env("SIDE", walk.max_side_speed), env("TURN", walk.turn_gain);
  env("LINE", plan.approach.line_lead_m), env("STOP", plan.stop_m);
  env("STILL", plan.approach.still_s), env("ARRIVED", plan.approach.arrived_m);
  env("STILL_SPEED", plan.approach.still_speed), env("SIDE_M", plan.approach.arrived_side_m);
  return plan;
}

// The search's score: a clearance counts most; short of one, how far past the plane the body's
// rearmost point got (less with the bar knocked off). Official attempts mostly fail as the head
// or hands reach the mat with the feet still down, so there the root's progress counts.
double score(const Attempt& at, bool official = false) {
  if (at.decision.is_null()) return -3;
  if (at.decision["call"] == "cleared") return 2;
  const double past = std::clamp(official ? at.root.x() : at.rear_x, -2.0, official ? 0.5 : 0.1);
  return at.decision["reason"] == "bar_dislodged" ? past - 0.5 : past;
}

// Attempts from the event's own start (the seed's bar 20 m ahead and 6 m to the left) on seeds
// 61-80, which no search or tuning used (the jump and the walk were tuned on seeds 1-20):
// `settings` at the 0.5 m bar. Prints the endings; returns the clearances.
int clearances_from_the_start(const nlohmann::json& settings) {
  int cleared = 0, n = 0;
  std::map<std::string, int> endings;
  for (std::uint64_t seed = 61; seed <= 80; ++seed, ++n) {
    const Attempt at = jump_once(seed, {}, settings);
    EXPECT_FALSE(at.decision.is_null()) << seed << ": undecided (the walk ran out of time)";
    if (at.decision.is_null()) continue;
    const bool over = at.decision["call"] == "cleared";
    cleared += over;
    if (over) {
      EXPECT_GT(at.jump_t, 10) << seed << ": the jump came after the walk";
      EXPECT_LT(at.bar_moved, 0.05) << seed << ": the bar stayed on its supports";
    }
    ++endings[over ? "cleared" : at.decision["reason"].get<std::string>()];
  }
  std::printf("cleared %d of %d: %s\n", cleared, n, nlohmann::json(endings).dump().c_str());
  return cleared;
}

// Paper (the bench's leap-over row at 0.5 m, the seed's 20 s): it walks the 21 m, arrives
// square to the bar and jumps over it: 13 of 20 when written (4 fell, 3 knocked the bar). Main's
// jumper (walking ~0.8 m/s straight at the stop, standing still 0.3 s, the first tucked jump)
// cleared 0 of these 20: 19 undecided, the 20 s gone in the walk, 1 bar knocked.
TEST(ScriptedHighJump, ClearsThePaperBarAfterWalkingFromTheSeedsStart) {
  EXPECT_GE(clearances_from_the_start({{"bar_height", 0.5}}), 8);  // 13 of 20 when written
}

// Official rules (the 2 kg bar on 40 x 60 mm supports, the 0.7 m mat, 60 s, the fan-shaped
// run-up) with the competition's first height set to 0.5 m: clearances over the bar onto the
// mat, the bar left on its supports: 12 of 20 when written (7 reached the mat before the root
// crossed the plane, 1 knocked the bar). Main's jumper: 0 of these 20 (19 `touched_beyond`: its
// head reached the mat before its root crossed the plane; 1 fell).
TEST(ScriptedHighJump, ClearsTheOfficialBarAfterWalkingFromTheStart) {
  EXPECT_GE(clearances_from_the_start({{"rules", "official"}, {"bar_height", 0.5}}),
            7);  // 12 of 20 when written
}

// The search that found the jump (run by hand: --gtest_also_run_disabled_tests; ITER=n
// iterations of CANDIDATES (150), each scored on SEEDS (1-4) with the bar BAR m right ahead
// (0.6; 0: the seed's, 21 m away) at HEIGHT (0.5 m), OFFICIAL for the official bar and rules;
// FROM="20 numbers" and SPREAD go on from an earlier run's means; the plan_from_env settings).
// Today's jump: 15 iterations of 120 from the first tucked jump, BAR=0.6 SEEDS=1-4 (the third
// iteration's best candidate; the means then collapsed onto knocking the bar), then 8 of 60 from
// it (SPREAD=0.5) from the seed's start: BAR=0 SEEDS=1-8 LINE=2 MAX_SPEED=2.5 STEP_S=0.25
// MAX_STEP=0.6 SIDE_M=0.5 SPM=1.5 STILL=0 STOP=0.8, the sixth iteration's means kept.
TEST(ScriptedHighJumpSearch, DISABLED_CrossEntropy) {
  const client::HighJumpPlan start = plan_from_env();
  std::vector<double> mean(client::control::StandingJump::kParameters);
  start.approach.jump.to(mean);
  std::vector<double> sd(mean.size(), 0.4);
  sd[18] = 0.15, sd[19] = 0.08;
  if (const char* from = std::getenv("FROM")) {
    std::istringstream in(from);
    for (double& m : mean) in >> m;
    for (double& d : sd) d *= std::getenv("SPREAD") ? std::atof(std::getenv("SPREAD")) : 1;
  }
  const double height = std::getenv("HEIGHT") ? std::atof(std::getenv("HEIGHT")) : 0.5;
  const double bar = std::getenv("BAR") ? std::atof(std::getenv("BAR")) : 0.6;  // 0: the seed's
  int first = 1, last = 4;
  if (const char* seeds = std::getenv("SEEDS")) std::sscanf(seeds, "%d-%d", &first, &last);
  nlohmann::json settings = {{"bar_height", height}};
  if (std::getenv("OFFICIAL")) settings["rules"] = "official";  // the whole preset, mat included
  const auto run = athletics::cross_entropy_run_from_env(10);
  athletics::cross_entropy_search(
      mean, sd,
      [&](const std::vector<double>& x) {
        client::HighJumpPlan plan = start;
        plan.approach.jump = client::control::StandingJump::from(x);
        double s = 0;
        for (int seed = first; seed <= last; ++seed)
          s += score(jump_once(seed, plan, settings, bar), settings.contains("rules"));
        return s / (last - first + 1);
      },
      run);
}

}  // namespace
}  // namespace olympics::sports::high_jump

namespace olympics::sports::high_jump {
namespace {

// The jumper's attempts printed (run by hand): BAR=x for the search's short approach, HEIGHT,
// JUMP="20 numbers" (a search's means), SEEDS=first-last.
TEST(ScriptedHighJumpProbe, DISABLED_Attempts) {
  const double bar = std::getenv("BAR") ? std::atof(std::getenv("BAR")) : 0;
  const double height = std::getenv("HEIGHT") ? std::atof(std::getenv("HEIGHT")) : 0.5;
  const client::HighJumpPlan plan = plan_from_env();
  int first = 1, last = 4;
  if (const char* seeds = std::getenv("SEEDS")) std::sscanf(seeds, "%d-%d", &first, &last);
  for (int seed = first; seed <= last; ++seed) {
    nlohmann::json settings = {{"bar_height", height}};
    if (const char* s = std::getenv("ATTEMPT_S")) settings["attempt_s"] = std::atof(s);
    if (std::getenv("OFFICIAL")) settings["rules"] = "official";  // the whole preset, mat included
    const Attempt at = jump_once(seed, plan, settings, bar);
    std::printf(
        "seed %d: %s rear %.2f, root at the end %.2f %.2f %.2f from the bar; jump at %.2f s from "
        "%.2f %.2f moving %.2f %.2f; first touch %s at %.2f s, %.2f m above the bar; bar moved "
        "%.3f m; highest body %.2f m\n",
        seed, at.decision.dump().c_str(), at.rear_x, at.root.x(), at.root.y(), at.root.z(),
        at.jump_t, at.jump_root.x(), at.jump_root.y(), at.jump_velocity.x(), at.jump_velocity.y(),
        at.first_touch.c_str(), at.touch_t, at.touch_top, at.bar_moved, at.top_z);
  }
}

}  // namespace
}  // namespace olympics::sports::high_jump
