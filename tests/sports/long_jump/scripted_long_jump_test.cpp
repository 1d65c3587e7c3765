// The scripted long jumper (clients/agent/scripted_long_jump.h), played in process: its attempts
// on seeds the search never saw are valid marks in the pit, and the search that found its jump.
#include "scripted_long_jump.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>

#include "../athletics/cross_entropy_search.h"
#include "athletics/athlete_probe.h"
#include "long_jump/long_jump_match.h"
#include "long_jump/long_jump_sport.h"
#include "registry.h"

namespace olympics::sports::long_jump {
namespace {

struct Jump {
  nlohmann::json decision;  // the attempt's mark or foul
  double feet_x = -1e9;     // the rearmost ankle's x at the decision, from the line
};

const nlohmann::json kOfficial = {{"rules", "official"}, {"attempts", 1}};

// One attempt by the scripted jumper. `line_x` > 0 moves the foul line (and the pit with it) to
// that distance from the start mark (as the `run_up` setting does): the search's short approach.
Jump jump_once(std::uint64_t seed, const client::LongJumpPlan& plan = {},
               const nlohmann::json& settings = kOfficial, double line_x = 0) {
  const auto& sport = dynamic_cast<const LongJumpSport&>(sport_or_throw("long_jump"));
  LongJumpRules rules = sport.rules(settings);
  if (line_x > 0) rules.line_x = line_x, rules.goal_x = line_x + 10;
  MatchSettings s{"solo", seed, 0.0, settings};
  s.time_limit_s = rules.attempt_s;
  LongJumpMatch m(rules, sport.modes().at("solo"), sport.layout("solo"), s);
  client::ScriptedLongJumpPolicy jumper(plan);
  jumper.start({"long_jump", "solo", 1.0 / 30,
                client::ObservationLayout::from_blocks(m.layout().observation), m.action_size()});
  std::vector<float> obs(m.obs_size()), act(m.action_size());
  Jump j;
  for (int tick = 0; tick < (rules.attempt_s + 1) * 30 && j.decision.is_null(); ++tick) {
    m.observe(0, obs);
    jumper.act(obs, act);
    m.step({std::span<const float>(act)});
    for (const auto& e : m.outcome().info["events"])
      if (e["call"] == "mark" || e["call"] == "foul") {
        j.decision = e;
        const core::Humanoid& h = m.athlete(0);
        j.feet_x =
            std::min(h.body_state(3).position.x(), h.body_state(7).position.x()) - rules.line_x;
      }
  }
  return j;
}

// The plan with what the environment changes (by hand), in both its stages: WALK, STOP, STILL,
// SPEED, ARRIVED, JUMP="20 numbers" (a search's means).
client::LongJumpPlan plan_from_env() {
  client::LongJumpPlan plan;
  for (client::LongJumpStage* stage : {&plan.standing, &plan.walk_up}) {
    client::control::JumpApproach& a = stage->approach;
    if (std::getenv("WALK")) a.walk.max_speed = std::atof(std::getenv("WALK"));
    if (std::getenv("STOP")) stage->stop_m = std::atof(std::getenv("STOP"));
    if (std::getenv("STILL")) a.still_s = std::atof(std::getenv("STILL"));
    if (std::getenv("SPEED")) a.still_speed = std::atof(std::getenv("SPEED"));
    if (std::getenv("ARRIVED")) a.arrived_m = std::atof(std::getenv("ARRIVED"));
    if (const char* jump = std::getenv("JUMP")) {
      std::vector<double> x(client::control::StandingJump::kParameters);
      std::istringstream in(jump);
      for (double& v : x) in >> v;
      a.jump = client::control::StandingJump::from(x);
    }
  }
  return plan;
}

// The search's score: a valid mark counts most, by its length; short of one, how far past the
// line the feet came down (a foul between the line and the pit, or a fall).
double score(const Jump& j, double pit_near) {
  if (j.decision.is_null()) return -3;
  if (j.decision["call"] == "mark") return pit_near + 1 + j.decision["mark"].get<double>();
  return std::clamp(j.feet_x, -2.0, pit_near + 1);
}

// Seeds the search never saw (it tuned on 1-4): official attempts from a start at the jumper's
// stop (the line 0.8 m ahead, so it stands there from the start) are marks in the pit, 1 m or
// more past the line, never a foul at the line (before the referee let a dive into the pit be,
// 2 of these 6 were `fell` in the air over the pit). From the full runway the walk leaves the
// body in another state and the jump fouls (docs/athletics.md).
TEST(ScriptedLongJump, MakesValidMarksFromAStandingStartAtItsStop) {
  int valid = 0, n = 0;
  double marks = 0;
  std::map<std::string, int> endings;
  for (std::uint64_t seed = 41; seed <= 46; ++seed, ++n) {
    const Jump j = jump_once(seed, {}, kOfficial, client::LongJumpPlan{}.standing.stop_m);
    ASSERT_FALSE(j.decision.is_null()) << seed;
    if (j.decision["call"] == "mark") {
      ++valid, marks += j.decision["mark"].get<double>(), ++endings["mark"];
      EXPECT_GE(j.decision["mark"].get<double>(), 1.0) << "in the pit, 1 m past the line";
    } else {
      ++endings[j.decision["reason"].get<std::string>()];
      EXPECT_GT(j.feet_x, 1.0) << seed << ": a foul before the feet were over the pit";
    }
  }
  std::printf("valid %d of %d, mean mark %.2f m: %s\n", valid, n, valid ? marks / valid : 0.0,
              nlohmann::json(endings).dump().c_str());
  EXPECT_GE(valid, 5);
}

// From the event's own start mark, 20 m behind the line: it walks down the runway (about 27 s)
// and jumps on arriving at its walk-up stop, still walking. Seeds the searches never saw (they
// tuned on 1-8); before the walk-up stage (it stood still at the stop after the walk) every one
// of these fouled or fell. Fouls here are landings short of the pit and falls, not a jump
// cut short by the time.
TEST(ScriptedLongJump, MakesValidMarksAfterWalkingDownTheRunway) {
  int valid = 0, n = 0;
  double marks = 0;
  std::map<std::string, int> endings;
  for (std::uint64_t seed = 61; seed <= 80; ++seed, ++n) {
    const Jump j = jump_once(seed);
    ASSERT_FALSE(j.decision.is_null()) << seed << ": no decision in the attempt's time";
    EXPECT_GT(j.decision["t"].get<double>(), 20.0) << seed << ": the walk takes most of 30 s";
    if (j.decision["call"] == "mark") {
      ++valid, marks += j.decision["mark"].get<double>(), ++endings["mark"];
      EXPECT_GE(j.decision["mark"].get<double>(), 1.0) << "in the pit, 1 m past the line";
    } else {
      ++endings[j.decision["reason"].get<std::string>()];
    }
  }
  std::printf("valid %d of %d, mean mark %.2f m: %s\n", valid, n, valid ? marks / valid : 0.0,
              nlohmann::json(endings).dump().c_str());
  EXPECT_GE(valid, 6);
}

// The search that found the jumps (run by hand: --gtest_also_run_disabled_tests; ITER=n
// iterations of CANDIDATES (150), each scored on SEEDS=n (4) seeds from 1 with the line LINE m
// from the start mark (0: the event's own 20 m; 0.8: the standing stage's stop, so that it stands
// there from the start; beyond LongJumpPlan::walk_up_beyond_m the walk-up stage's: the walked-up
// jump was searched with LINE=6, a 5 m walk whose arrival is like the runway's, at a quarter of its
// cost); FROM="20 numbers" and SPREAD go on from an earlier run's means; the plan_from_env
// settings).
TEST(ScriptedLongJumpSearch, DISABLED_CrossEntropy) {
  std::vector<double> mean(client::control::StandingJump::kParameters);
  const double line = std::getenv("LINE") ? std::atof(std::getenv("LINE")) : 0.8;
  const client::LongJumpPlan start;
  const bool walk_up = line <= 0 || line > start.walk_up_beyond_m;  // 0: the full runway
  (walk_up ? start.walk_up : start.standing).approach.jump.to(mean);
  std::vector<double> sd(mean.size(), 0.4);
  sd[18] = 0.15, sd[19] = 0.08;
  if (const char* from = std::getenv("FROM")) {
    std::istringstream in(from);
    for (double& m : mean) in >> m;
    for (double& d : sd) d *= std::getenv("SPREAD") ? std::atof(std::getenv("SPREAD")) : 1;
  }
  const auto run = athletics::cross_entropy_run_from_env(10);
  const std::uint64_t seeds = std::getenv("SEEDS") ? std::atoi(std::getenv("SEEDS")) : 4;
  athletics::cross_entropy_search(
      mean, sd,
      [&](const std::vector<double>& x) {
        client::LongJumpPlan plan = plan_from_env();  // the line's distance picks the stage
        plan.standing.approach.jump = plan.walk_up.approach.jump =
            client::control::StandingJump::from(x);
        double s = 0;
        for (std::uint64_t seed = 1; seed <= seeds; ++seed)
          s += score(jump_once(seed, plan, kOfficial, line), 1.0);
        return s / static_cast<double>(seeds);
      },
      run);
}

}  // namespace
}  // namespace olympics::sports::long_jump

namespace olympics::sports::long_jump {
namespace {

// The jumper's attempts printed (run by hand): LINE=x for the search's short approach.
TEST(ScriptedLongJumpProbe, DISABLED_Attempts) {
  const double line = std::getenv("LINE") ? std::atof(std::getenv("LINE")) : 0;
  int first = 1, last = 4;
  if (const char* seeds = std::getenv("SEEDS")) std::sscanf(seeds, "%d-%d", &first, &last);
  for (std::uint64_t seed = first; seed <= static_cast<std::uint64_t>(last); ++seed) {
    const client::LongJumpPlan plan = plan_from_env();
    const Jump j = jump_once(seed, plan, kOfficial, line);
    std::printf("seed %d: %s feet %.2f\n", static_cast<int>(seed), j.decision.dump().c_str(),
                j.feet_x);
    std::fflush(stdout);
  }
}

}  // namespace
}  // namespace olympics::sports::long_jump
