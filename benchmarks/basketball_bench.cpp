#include "basketball_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "basketball/basketball_match.h"
#include "basketball_dribble_bench.h"
#include "bench_support.h"
#include "core/humanoid_assets.h"
#include "registry.h"
#include "scripted_basketball.h"
#include "scripted_basketball_team.h"

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

// Mean and normal 95% interval of per-game values.
nlohmann::json mean_ci95(const std::vector<double>& v) {
  double mean = 0, sq = 0;
  for (double x : v) mean += x;
  mean /= v.size();
  for (double x : v) sq += (x - mean) * (x - mean);
  const double half = v.size() > 1 ? 1.96 * std::sqrt(sq / (v.size() - 1) / v.size()) : 0.0;
  return {{"mean", mean}, {"ci95", {mean - half, mean + half}}};
}

// Scripted 1v1 games, both slots the scripted team player, `game_s` seconds each. Points and falls
// are per game scaled to 10 minutes and per minute; shots are the players' swings (a heave: from
// beyond the set shot's reach, the long shot; a throw out: the ball thrown out with the rim
// behind), made is the counted baskets over them.
nlohmann::json scripted_games(const std::vector<std::uint64_t>& seeds, double game_s) {
  std::vector<double> points[2], falls_per_min;
  int shots = 0, heaves = 0, throws_out = 0, made = 0;
  std::map<std::string, int> stoppages;
  nlohmann::json games = nlohmann::json::array();
  for (const std::uint64_t seed : seeds) {
    auto m = sports::sport_or_throw("basketball").create({"1v1", seed, game_s, {}});
    const auto& match = dynamic_cast<const sports::basketball::BasketballMatch&>(*m);
    const client::MatchInfo info = in_process_match_info("basketball", "1v1", *m);
    client::ScriptedBasketballTeamPlayer players[2];
    for (auto& p : players) p.start(info);
    std::vector<float> obs[2], act[2];
    int falls = 0;
    while (!m->outcome().match_over) {
      for (int s = 0; s < 2; ++s) {
        obs[s].resize(m->obs_size()), act[s].resize(m->action_size());
        m->observe(s, obs[s]);
        players[s].act(obs[s], act[s]);
      }
      m->step({std::span<const float>(act[0]), std::span<const float>(act[1])});
      const nlohmann::json& info_json = m->outcome().info;
      if (info_json.contains("events"))
        for (const auto& e : info_json["events"]) {
          const std::string call = e.value("call", "");
          falls += call == "fall";
          made += call == "basket" && e.value("points", 0) > 0;
          if (call != "fall" && call != "stood_up" && call != "restart" && call != "basket")
            ++stoppages[call];
        }
    }
    const double minutes = m->tick() * m->control_dt() / 60;
    const auto& score = match.referee().score();
    for (int side = 0; side < 2; ++side) points[side].push_back(score[side] * 10 / minutes);
    falls_per_min.push_back(falls / minutes);
    for (const auto& p : players)
      shots += p.shots(), heaves += p.heaves(), throws_out += p.throws_out();
    games.push_back({{"seed", seed},
                     {"minutes", minutes},
                     {"score", {score[0], score[1]}},
                     {"falls", falls},
                     {"shots", players[0].shots() + players[1].shots()}});
  }
  return {{"games", static_cast<int>(seeds.size())},
          {"game_s", game_s},
          {"points_per_10_min_side_0", mean_ci95(points[0])},
          {"points_per_10_min_side_1", mean_ci95(points[1])},
          {"falls_per_min", mean_ci95(falls_per_min)},
          {"shots", shots},
          {"heaves", heaves},
          {"throws_out", throws_out},
          {"made", made},
          {"made_share_ci95", wilson_95(made, std::max(shots, 1))},
          {"stoppages", stoppages},
          {"per_game", games}};
}

}  // namespace

nlohmann::json run_basketball_bench(const BasketballBenchOptions& o) {
  const std::string named = named_or_evaluation_seeds(o.seeds, o.throws);
  const std::vector<std::uint64_t> seeds = episode_seeds(named, 0);
  nlohmann::json report = {{"free_throw", nlohmann::json::object()}, {"seeds", named}};
  for (const auto& p : o.free_throws ? o.policies : std::vector<std::string>{})
    report["free_throw"][p] =
        p == "scripted" ? scripted_throws(seeds, o.per_throw) : free_throws(p, seeds);
  // The scripted shooter aims by the ballistic solution: from nearer lines too.
  const bool scripted = o.free_throws && std::find(o.policies.begin(), o.policies.end(),
                                                   "scripted") != o.policies.end();
  for (double d : scripted ? o.scripted_distances : std::vector<double>{}) {
    char key[32];
    std::snprintf(key, sizeof key, "%g", d);
    report["scripted_by_distance"][key] =
        free_throws("scripted", seeds, {{"free_throw_distance", d}});
  }
  if (!o.game_seeds.empty()) {
    report["scripted_1v1"] = scripted_games(episode_seeds(o.game_seeds, 0), o.game_s);
    report["scripted_1v1"]["seeds"] = o.game_seeds;
  }
  if (!o.dribble_seeds.empty()) {
    report["scripted_dribble"] =
        scripted_dribbles(episode_seeds(o.dribble_seeds, 0), o.dribble_s, o.per_dribble);
    report["scripted_dribble"]["seeds"] = o.dribble_seeds;
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
  if (!r["free_throw"].empty()) std::printf("seeds %s\n", r["seeds"].get<std::string>().c_str());
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
  if (r.contains("scripted_1v1")) {
    const auto& g = r["scripted_1v1"];
    auto rate = [](const nlohmann::json& f) {
      char text[80];
      std::snprintf(text, sizeof text, "%.2f (95%% interval %.2f-%.2f)", f["mean"].get<double>(),
                    f["ci95"][0].get<double>(), f["ci95"][1].get<double>());
      return std::string(text);
    };
    std::printf(
        "scripted 1v1, %d games of %g s (seeds %s): points per 10 minutes, side 0 %s, side 1 %s; "
        "shots %d (%d heaves from beyond reach), made %d (95%% interval %.1f-%.1f%%); falls per "
        "minute %s; stoppages %s\n",
        g["games"].get<int>(), g["game_s"].get<double>(), g["seeds"].get<std::string>().c_str(),
        rate(g["points_per_10_min_side_0"]).c_str(), rate(g["points_per_10_min_side_1"]).c_str(),
        g["shots"].get<int>(), g["heaves"].get<int>(), g["made"].get<int>(),
        100 * g["made_share_ci95"][0].get<double>(), 100 * g["made_share_ci95"][1].get<double>(),
        rate(g["falls_per_min"]).c_str(), g["stoppages"].dump().c_str());
  }
  if (r.contains("scripted_dribble")) {
    const auto& d = r["scripted_dribble"];
    std::printf(
        "scripted dribble, %d episodes of %g s (seeds %s): consecutive dribbles before the ball "
        "was lost, median %d, p10 %d; one or more in %d (95%% interval %.1f-%.1f%%), two or more "
        "in %d, three or more in %d; kept to the end %.1f%% (95%% interval %.1f-%.1f%%); episodes "
        "with a fall %d (when, p10 / median / p90 s: %s)\n",
        d["episodes"].get<int>(), d["seconds"].get<double>(), d["seeds"].get<std::string>().c_str(),
        d["dribbles_median"].get<int>(), d["dribbles_p10"].get<int>(), d["one_or_more"].get<int>(),
        100 * d["one_or_more_ci95"][0].get<double>(), 100 * d["one_or_more_ci95"][1].get<double>(),
        d["two_or_more"].get<int>(), d["three_or_more"].get<int>(),
        100 * d["kept_share"].get<double>(), 100 * d["kept_ci95"][0].get<double>(),
        100 * d["kept_ci95"][1].get<double>(), d["falls"].get<int>(),
        d["fell_at_s_p10_median_p90"].dump().c_str());
  }
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
