#include "racket_bench.h"

#include <algorithm>
#include <cstdio>

#include "bench_support.h"
#include "core/humanoid_assets.h"
#include "core/humanoid_scene.h"
#include "policies.h"
#include "racket/racket_equipment.h"
#include "racket/racket_match.h"
#include "registry.h"

namespace olympics::bench {
namespace {

struct EpisodeStats {
  int episodes = 0, balls = 0, touched = 0, first_ball_touched = 0, returns_in = 0, falls = 0;
  long ticks = 0;
};

// Plays ball-return episodes with a policy; counts balls launched, balls touched, returns in.
EpisodeStats ball_return(const std::string& sport, const std::string& policy_name, int episodes) {
  const auto& s = sports::sport_or_throw(sport);
  EpisodeStats st;
  for (int e = 0; e < episodes; ++e) {
    auto match = s.create({"ball_return", static_cast<std::uint64_t>(e + 1), 60.0, {}});
    auto* racket = dynamic_cast<sports::racket::RacketMatch*>(match.get());
    auto policy = client::make_policy(policy_name, e + 1);
    policy->start(in_process_match_info(sport, "ball_return", *match));
    std::vector<float> obs(match->obs_size()), act(match->action_size());
    int touches_this_ball = 0, balls = 1, touched = 0;
    bool first_touched = false;
    while (!match->outcome().match_over) {
      match->observe(0, obs);
      policy->act(obs, act);
      match->step({std::span<const float>(act)});
      for (const auto& ev : match->outcome().info.value("events", nlohmann::json::array())) {
        const std::string call = ev.value("call", "");
        if (call == "hit" && touches_this_ball++ == 0) {
          ++touched;
          if (balls == 1) first_touched = true;
        }
        if (call == "return_in") ++balls, touches_this_ball = 0;
        if (call == "fall") ++st.falls;
      }
    }
    st.episodes++;
    st.balls += balls;
    st.touched += touched;
    st.first_ball_touched += first_touched;
    st.returns_in += racket->returns_in(0);
    st.ticks += match->tick();
  }
  return st;
}

}  // namespace

nlohmann::json run_racket_bench(const RacketBenchOptions& o) {
  nlohmann::json report = {{"episodes", o.episodes}, {"sports", nlohmann::json::object()}};
  for (const std::string& sport : o.sports) {
    nlohmann::json& r = report["sports"][sport];
    for (const std::string& policy : o.policies) {
      const EpisodeStats st = ball_return(sport, policy, o.episodes);
      r["ball_return"][policy] = {{"episodes", st.episodes},
                                  {"balls", st.balls},
                                  {"balls_touched", st.touched},
                                  {"first_ball_touched", st.first_ball_touched},
                                  {"returns_in", st.returns_in},
                                  {"falls", st.falls},
                                  {"touch_fraction", double(st.touched) / st.balls}};
    }
    if (!o.speed) continue;
    core::ModelSpec players = core::load_humanoid(core::HumanoidKind::Smpl);
    sports::equipment::attach_equipment(players, sport == "tennis"
                                                     ? sports::racket::tennis_racket()
                                                     : sports::racket::table_tennis_paddle());
    r["speed_1v1"] = speed_vs_bare(sport, players, o.seconds, o.repeats, /*ticks=*/300);
  }
  return report;
}

void print_racket_report(const nlohmann::json& report) {
  for (const auto& [sport, r] : report["sports"].items()) {
    std::printf("%s\n", sport.c_str());
    for (const auto& [policy, b] : r["ball_return"].items())
      std::printf(
          "  ball_return %-8s %d episodes: %d balls, %d touched (%.1f%%), first ball touched in "
          "%d, %d returns in, %d falls\n",
          policy.c_str(), b["episodes"].get<int>(), b["balls"].get<int>(),
          b["balls_touched"].get<int>(), 100 * b["touch_fraction"].get<double>(),
          b["first_ball_touched"].get<int>(), b["returns_in"].get<int>(), b["falls"].get<int>());
    if (!r.contains("speed_1v1")) continue;
    const auto& s = r["speed_1v1"];
    std::printf("  1v1 ticks/s on one core: match %.0f, bare physics %.0f, ratio %.2f\n",
                s["match_ticks_per_s"].get<double>(), s["bare_physics_ticks_per_s"].get<double>(),
                s["ratio"].get<double>());
  }
}

}  // namespace olympics::bench
