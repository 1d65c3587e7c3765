#include "basketball_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "basketball/basketball_match.h"
#include "bench_support.h"
#include "core/humanoid_assets.h"
#include "registry.h"
#include "scripted_basketball.h"

namespace olympics::bench {
namespace {

nlohmann::json free_throws(const std::string& policy, const std::vector<std::uint64_t>& seeds,
                           const nlohmann::json& options = nlohmann::json::object()) {
  int made = 0;
  std::map<std::string, int> endings;
  for (const std::uint64_t seed : seeds) {
    const auto match = play_in_process("basketball", {"free_throw", seed, 0.0, options}, {policy});
    made += match->outcome().reason == "basket";
    ++endings[match->outcome().reason];
  }
  const int throws = static_cast<int>(seeds.size());
  return {{"throws", throws},
          {"made", static_cast<double>(made) / throws},
          {"made_ci95", wilson_95(made, throws)},
          {"endings", endings}};
}

// The scripted shooter's throws, with how the ball left its hands: its speed on the first tick it
// is clear of the palms (its centre 0.2 m from their midpoint; so up to a tick of free flight
// after the release, which gravity slows by at most 0.33 m/s) against the launch speed of the
// ballistic solution the shooter aimed by, and its elevation against the solution's 60 degrees.
nlohmann::json scripted_throws(const std::vector<std::uint64_t>& seeds, bool per_throw) {
  int made = 0, released = 0, within = 0;
  std::map<std::string, int> endings;
  std::vector<double> errors;
  nlohmann::json throws = nlohmann::json::array();
  for (const std::uint64_t seed : seeds) {
    auto m = sports::sport_or_throw("basketball").create({"free_throw", seed, 0.0, {}});
    const auto& match = dynamic_cast<const sports::basketball::BasketballMatch&>(*m);
    client::ScriptedBasketballPolicy shooter;
    shooter.start(in_process_match_info("basketball", "free_throw", *m));
    std::vector<float> obs(m->obs_size()), act(m->action_size());
    const core::Humanoid& h = match.scene().humanoid(0);
    auto palms = [&] {  // the palm boxes' centres (HUMANOID-SMPLX.md), their midpoint
      const auto l = h.body_state(17), r = h.body_state(36);
      return Eigen::Vector3d(
          0.5 * (l.position + l.orientation * Eigen::Vector3d(-.0031, .0523, -.0013) + r.position +
                 r.orientation * Eigen::Vector3d(-.0029, -.0537, -.0044)));
    };
    const int swing_tick = static_cast<int>(client::FreeThrowShot{}.shot_s * 30);
    nlohmann::json t = {{"seed", seed}};
    bool clear = false;
    for (int tick = 0; !m->outcome().match_over; ++tick) {
      m->observe(0, obs);
      shooter.act(obs, act);
      m->step({std::span<const float>(act)});
      if (clear || tick < swing_tick || (match.ball().position() - palms()).norm() < 0.2) continue;
      clear = true;
      const Eigen::Vector3d v = match.ball().velocity();
      const double speed = v.norm(), wanted = shooter.aim().launch_speed;
      const double error = std::abs(speed - wanted);
      ++released;
      within += error <= 0.2;
      errors.push_back(error);
      t["ball_speed"] = speed;
      t["solution_speed"] = wanted;
      t["ball_elevation_deg"] = std::atan2(v.z(), v.head<2>().norm()) * 180 / M_PI;
      t["release_trim_rad"] = shooter.trim();
    }
    const std::string reason = m->outcome().reason;
    t["reason"] = reason;
    made += reason == "basket";
    ++endings[reason];
    if (per_throw) throws.push_back(t);
  }
  std::sort(errors.begin(), errors.end());
  auto quantile = [&](double q) {
    return errors.empty() ? 0.0 : errors[static_cast<size_t>(q * (errors.size() - 1))];
  };
  const int n = static_cast<int>(seeds.size());
  nlohmann::json f = {{"throws", n},
                      {"made", static_cast<double>(made) / n},
                      {"made_ci95", wilson_95(made, n)},
                      {"endings", endings},
                      {"released", released},
                      {"release_speed_within_0_2", static_cast<double>(within) / n},
                      {"release_speed_within_0_2_ci95", wilson_95(within, n)},
                      {"release_speed_error_median", quantile(0.5)},
                      {"release_speed_error_q75", quantile(0.75)}};
  if (per_throw) f["per_throw"] = throws;
  return f;
}

}  // namespace

nlohmann::json run_basketball_bench(const BasketballBenchOptions& o) {
  const std::vector<std::uint64_t> seeds = episode_seeds(o.seeds, o.throws);
  nlohmann::json report = {{"free_throw", nlohmann::json::object()},
                           {"seeds", o.seeds.empty() ? "1-" + std::to_string(o.throws) : o.seeds}};
  for (const auto& p : o.policies)
    report["free_throw"][p] =
        p == "scripted" ? scripted_throws(seeds, o.per_throw) : free_throws(p, seeds);
  // The scripted shooter aims by the ballistic solution: from nearer lines too.
  const bool scripted =
      std::find(o.policies.begin(), o.policies.end(), "scripted") != o.policies.end();
  for (double d : scripted ? o.scripted_distances : std::vector<double>{}) {
    char key[32];
    std::snprintf(key, sizeof key, "%g", d);
    report["scripted_by_distance"][key] =
        free_throws("scripted", seeds, {{"free_throw_distance", d}});
  }
  if (o.speed) {
    static const core::ModelSpec smplx = core::load_humanoid(core::HumanoidKind::SmplX);
    for (const char* mode : {"1v1", "2v2"})
      report["speed_" + std::string(mode)] =
          speed_vs_bare("basketball", smplx, o.seconds, o.repeats, 45, mode);
  }
  return report;
}

void print_basketball_report(const nlohmann::json& r) {
  std::printf("seeds %s\n", r["seeds"].get<std::string>().c_str());
  for (const auto& [policy, f] : r["free_throw"].items())
    std::printf("free throw, %-9s %d throws: made %.1f%% (95%% interval %.1f-%.1f%%); endings %s\n",
                policy.c_str(), f["throws"].get<int>(), 100 * f["made"].get<double>(),
                100 * f["made_ci95"][0].get<double>(), 100 * f["made_ci95"][1].get<double>(),
                f["endings"].dump().c_str());
  if (const auto& f = r["free_throw"]; f.contains("scripted"))
    std::printf(
        "free throw, scripted: the ball's speed leaving the hands within 0.2 m/s of the ballistic "
        "solution's in %.1f%% (95%% interval %.1f-%.1f%%); off by %.2f m/s in the median throw, "
        "%.2f at the 3rd quartile\n",
        100 * f["scripted"]["release_speed_within_0_2"].get<double>(),
        100 * f["scripted"]["release_speed_within_0_2_ci95"][0].get<double>(),
        100 * f["scripted"]["release_speed_within_0_2_ci95"][1].get<double>(),
        f["scripted"]["release_speed_error_median"].get<double>(),
        f["scripted"]["release_speed_error_q75"].get<double>());
  if (r.contains("scripted_by_distance"))
    for (const auto& [d, f] : r["scripted_by_distance"].items())
      std::printf(
          "free throw, scripted from %s m (the rule's line: 4.6 m), %d throws: made %.1f%% (95%% "
          "interval %.1f-%.1f%%)\n",
          d.c_str(), f["throws"].get<int>(), 100 * f["made"].get<double>(),
          100 * f["made_ci95"][0].get<double>(), 100 * f["made_ci95"][1].get<double>());
  for (const char* mode : {"1v1", "2v2"}) {
    const std::string key = "speed_" + std::string(mode);
    if (!r.contains(key)) continue;
    const auto& v = r[key];
    std::printf(
        "%s ticks/s on one core (zero actions, first %d ticks): match %.0f, bare physics of as "
        "many SMPL-X humanoids %.0f, ratio %.2f\n",
        mode, v["ticks_per_match"].get<int>(), v["match_ticks_per_s"].get<double>(),
        v["bare_physics_ticks_per_s"].get<double>(), v["ratio"].get<double>());
  }
}

}  // namespace olympics::bench
