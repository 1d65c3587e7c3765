#include "racket_bench.h"

#include <algorithm>
#include <chrono>
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

using Clock = std::chrono::steady_clock;

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

// Ticks per second of a 1v1 match with zero actions (restarted whenever it ends).
double match_ticks_per_s(const std::string& sport, double seconds) {
  const auto& s = sports::sport_or_throw(sport);
  std::vector<float> act(69, 0.0f);
  std::vector<std::span<const float>> actions(2, std::span<const float>(act));
  std::vector<float> obs;
  long ticks = 0;
  std::uint64_t seed = 1;
  const auto start = Clock::now();
  while (std::chrono::duration<double>(Clock::now() - start).count() < seconds) {
    auto match = s.create({"1v1", seed++, 60.0, {}});
    obs.resize(match->obs_size());
    for (int t = 0; t < 300 && !match->outcome().match_over; ++t, ++ticks) {
      for (int slot = 0; slot < 2; ++slot) match->observe(slot, obs);
      match->step(actions);
    }
  }
  return ticks / std::chrono::duration<double>(Clock::now() - start).count();
}

// Ticks per second of the same two equipped humanoids with nothing else.
double bare_ticks_per_s(const sports::equipment::EquipmentSpec& equipment, double seconds) {
  core::ModelSpec spec = core::load_humanoid(core::HumanoidKind::Smpl);
  sports::equipment::attach_equipment(spec, equipment);
  std::vector<float> act(69, 0.0f);
  long ticks = 0;
  const auto start = Clock::now();
  while (std::chrono::duration<double>(Clock::now() - start).count() < seconds) {
    core::HumanoidScene scene;
    scene.add_humanoid(spec, {{-2, 0, 0}, 0});
    scene.add_humanoid(spec, {{2, 0, 0}, M_PI});
    for (int t = 0; t < 300; ++t, ++ticks) {
      for (int i = 0; i < 2; ++i) scene.set_action(i, act);
      scene.tick();
    }
  }
  return ticks / std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

nlohmann::json run_racket_bench(const RacketBenchOptions& o) {
  nlohmann::json report = {{"episodes", o.episodes}, {"sports", nlohmann::json::object()}};
  for (const std::string sport : {"tennis", "table_tennis"}) {
    nlohmann::json& r = report["sports"][sport];
    for (const std::string policy : {"scripted", "zero"}) {
      const EpisodeStats st = ball_return(sport, policy, o.episodes);
      r["ball_return"][policy] = {{"episodes", st.episodes},
                                  {"balls", st.balls},
                                  {"balls_touched", st.touched},
                                  {"first_ball_touched", st.first_ball_touched},
                                  {"returns_in", st.returns_in},
                                  {"falls", st.falls},
                                  {"touch_fraction", double(st.touched) / st.balls}};
    }
    const auto equipment =
        sport == "tennis" ? sports::racket::tennis_racket() : sports::racket::table_tennis_paddle();
    std::vector<double> match, bare, ratio;
    for (int i = 0; i < o.repeats; ++i) {  // interleaved, so drift hits both alike
      match.push_back(match_ticks_per_s(sport, o.seconds));
      bare.push_back(bare_ticks_per_s(equipment, o.seconds));
      ratio.push_back(match.back() / bare.back());
    }
    r["speed_1v1"] = {{"match_ticks_per_s", median(match)},
                      {"bare_physics_ticks_per_s", median(bare)},
                      {"ratio", median(ratio)}};
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
    const auto& s = r["speed_1v1"];
    std::printf("  1v1 ticks/s on one core: match %.0f, bare physics %.0f, ratio %.2f\n",
                s["match_ticks_per_s"].get<double>(), s["bare_physics_ticks_per_s"].get<double>(),
                s["ratio"].get<double>());
  }
}

}  // namespace olympics::bench
