// The scripted high jumper (clients/agent/scripted_high_jump.h), played in process: on seeds the
// search never saw it clears the seed's lowest bar from a standing start before it, and the
// search that found its jump.
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
};

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
  for (int tick = 0; tick < (rules.attempt_s + 1) * 30 && at.decision.is_null(); ++tick) {
    m.observe(0, obs);
    jumper.act(obs, act);
    m.step({std::span<const float>(act)});
    for (const auto& e : m.outcome().info["events"])
      if (e["call"] == "cleared" || e["call"] == "failure") {
        at.decision = e;
        const core::Humanoid& h = m.athlete(0);
        double rear = 1e9;
        for (int b = 0; b < h.body_count(); ++b)
          rear = std::min(rear, h.body_state(b).position.x());
        at.rear_x = rear - rules.bar_x;
      }
  }
  at.root = m.athlete(0).body_state(0).position - Eigen::Vector3d(rules.bar_x, rules.bar_y, 0);
  return at;
}

// The search's score: a clearance counts most; short of one, how far past the plane the body's
// rearmost point got (less with the bar knocked off).
double score(const Attempt& at) {
  if (at.decision.is_null()) return -3;
  if (at.decision["call"] == "cleared") return 2;
  const double past = std::clamp(at.rear_x, -2.0, 0.1);
  return at.decision["reason"] == "bar_dislodged" ? past - 0.5 : past;
}

// Seeds the search never saw (it tuned on 1-4): paper attempts at the seed's lowest bar
// (0.5 m, its 8 kg crossbar) from a start right before the bar's middle (0.6 m ahead) are
// clearances: every body past the plane, the bar still on its supports. From the seed's start
// (21 m away) the walk takes the 20 s of an attempt (docs/athletics.md).
TEST(ScriptedHighJump, ClearsTheSeedsLowestBarFromAStandingStart) {
  int cleared = 0, n = 0;
  std::map<std::string, int> endings;
  for (std::uint64_t seed = 41; seed <= 46; ++seed, ++n) {
    const Attempt at = jump_once(seed, {}, {{"bar_height", 0.5}}, 0.6);
    ASSERT_FALSE(at.decision.is_null()) << seed;
    const bool over = at.decision["call"] == "cleared";
    cleared += over;
    if (over) {
      EXPECT_GT(at.rear_x, 0.1) << seed;
    }
    ++endings[over ? "cleared" : at.decision["reason"].get<std::string>()];
  }
  std::printf("cleared %d of %d: %s\n", cleared, n, nlohmann::json(endings).dump().c_str());
  EXPECT_GE(cleared, n - 1);
}

// The search that found the jump (run by hand: --gtest_also_run_disabled_tests; ITER=n
// iterations of CANDIDATES (150), each scored on seeds 1-4 with the bar right ahead at HEIGHT
// (0.5 m); FROM="20 numbers" and SPREAD go on from an earlier run's means).
TEST(ScriptedHighJumpSearch, DISABLED_CrossEntropy) {
  std::vector<double> mean(client::control::StandingJump::kParameters);
  client::HighJumpPlan::tucked_jump().to(mean);
  std::vector<double> sd(mean.size(), 0.4);
  sd[18] = 0.15, sd[19] = 0.08;
  if (const char* from = std::getenv("FROM")) {
    std::istringstream in(from);
    for (double& m : mean) in >> m;
    for (double& d : sd) d *= std::getenv("SPREAD") ? std::atof(std::getenv("SPREAD")) : 1;
  }
  const double height = std::getenv("HEIGHT") ? std::atof(std::getenv("HEIGHT")) : 0.5;
  athletics::CrossEntropyRun run;
  run.iterations = std::getenv("ITER") ? std::atoi(std::getenv("ITER")) : 10;
  run.candidates = std::getenv("CANDIDATES") ? std::atoi(std::getenv("CANDIDATES")) : 150;
  run.elite = run.candidates / 10;
  athletics::cross_entropy_search(
      mean, sd,
      [&](const std::vector<double>& x) {
        client::HighJumpPlan plan;
        plan.approach.jump = client::control::StandingJump::from(x);
        double s = 0;
        for (std::uint64_t seed = 1; seed <= 4; ++seed)
          s += score(jump_once(seed, plan, {{"bar_height", height}}, 0.6));
        return s / 4;
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
  client::HighJumpPlan plan;
  if (const char* jump = std::getenv("JUMP")) {
    std::vector<double> x(client::control::StandingJump::kParameters);
    std::istringstream in(jump);
    for (double& v : x) in >> v;
    plan.approach.jump = client::control::StandingJump::from(x);
  }
  int first = 1, last = 4;
  if (const char* seeds = std::getenv("SEEDS")) std::sscanf(seeds, "%d-%d", &first, &last);
  for (int seed = first; seed <= last; ++seed) {
    nlohmann::json settings = {{"bar_height", height}};
    if (const char* s = std::getenv("ATTEMPT_S")) settings["attempt_s"] = std::atof(s);
    if (std::getenv("OFFICIAL")) settings["measure"] = "official", settings["bar"] = "official";
    const Attempt at = jump_once(seed, plan, settings, bar);
    std::printf("seed %d: %s rear %.2f, root at the end %.2f %.2f %.2f from the bar\n", seed,
                at.decision.dump().c_str(), at.rear_x, at.root.x(), at.root.y(), at.root.z());
  }
}

}  // namespace
}  // namespace olympics::sports::high_jump
