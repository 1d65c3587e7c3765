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
    const Jump j = jump_once(seed, {}, kOfficial, client::LongJumpPlan{}.stop_m);
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

// The search that found the jump (run by hand: --gtest_also_run_disabled_tests; ITER=n
// iterations of CANDIDATES (150), each scored on seeds 1-4 with the line `stop_m` from the
// start, so that the jumper stands at its stop from the start: the runway's walk is left out, it
// takes half a minute; FROM="20 numbers" and SPREAD go on from an earlier run's means).
TEST(ScriptedLongJumpSearch, DISABLED_CrossEntropy) {
  std::vector<double> mean(client::control::StandingJump::kParameters);
  const client::LongJumpPlan start;
  start.approach.jump.to(mean);
  std::vector<double> sd(mean.size(), 0.4);
  sd[18] = 0.15, sd[19] = 0.08;
  if (const char* from = std::getenv("FROM")) {
    std::istringstream in(from);
    for (double& m : mean) in >> m;
    for (double& d : sd) d *= std::getenv("SPREAD") ? std::atof(std::getenv("SPREAD")) : 1;
  }
  athletics::CrossEntropyRun run;
  run.iterations = std::getenv("ITER") ? std::atoi(std::getenv("ITER")) : 10;
  run.candidates = std::getenv("CANDIDATES") ? std::atoi(std::getenv("CANDIDATES")) : 150;
  run.elite = run.candidates / 10;
  const double line = std::getenv("LINE") ? std::atof(std::getenv("LINE")) : 0.8;
  const std::uint64_t seeds = std::getenv("SEEDS") ? std::atoi(std::getenv("SEEDS")) : 4;
  athletics::cross_entropy_search(
      mean, sd,
      [&](const std::vector<double>& x) {
        client::LongJumpPlan plan;
        plan.approach.jump = client::control::StandingJump::from(x);
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
    client::LongJumpPlan plan;
    if (std::getenv("WALK")) plan.approach.walk_speed = std::atof(std::getenv("WALK"));
    if (std::getenv("STOP")) plan.stop_m = std::atof(std::getenv("STOP"));
    if (std::getenv("STILL")) plan.approach.still_s = std::atof(std::getenv("STILL"));
    if (const char* jump = std::getenv("JUMP")) {  // 20 numbers: a search's means
      std::vector<double> x(client::control::StandingJump::kParameters);
      std::istringstream in(jump);
      for (double& v : x) in >> v;
      plan.approach.jump = client::control::StandingJump::from(x);
    }
    const Jump j = jump_once(seed, plan, kOfficial, line);
    std::printf("seed %d: %s feet %.2f\n", static_cast<int>(seed), j.decision.dump().c_str(),
                j.feet_x);
    std::fflush(stdout);
  }
}

}  // namespace
}  // namespace olympics::sports::long_jump
