#include "athletics_bench.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <random>

#include "bench_support.h"
#include "core/humanoid_assets.h"
#include "hurdles_bench.h"
#include "javelin_bench.h"
#include "scripted_long_jump.h"

namespace olympics::bench {
namespace {

// A standing long jump's start mark: where the scripted jumper stops behind the line to jump
// from a standing start, so the row measures its jump without its walk-up.
const double kStandingRunUp = client::LongJumpPlan{}.standing.stop_m;

// The attempt's decision (the first `mark`/`foul`/`cleared`/`failure` event) of a solo episode.
nlohmann::json decision(const std::string& sport, const nlohmann::json& options, std::uint64_t seed,
                        const std::string& policy) {
  nlohmann::json decided;
  play_in_process(sport, {"solo", seed, 0.0, options}, {policy}, [&](const sports::SportMatch& m) {
    for (const auto& e : m.outcome().info["events"])
      if (decided.is_null() && e["call"] != "fall") decided = e;
  });
  return decided;
}

// Official long jumps, one attempt each, from the start mark `run_up` m behind the foul line
// (the rules' 20 m, or a standing long jump's 0.8 m: where the scripted jumper stops to jump).
nlohmann::json long_jumps(const std::string& policy, const std::vector<std::uint64_t>& seeds,
                          double run_up) {
  int valid = 0, fouls = 0;
  double marks = 0;
  std::map<std::string, int> endings;
  const nlohmann::json options = {{"rules", "official"}, {"attempts", 1}, {"run_up", run_up}};
  for (const std::uint64_t seed : seeds) {
    const nlohmann::json e = decision("long_jump", options, seed, policy);
    if (e.is_null()) {
      ++endings["undecided"];
    } else if (e["call"] == "mark") {
      ++valid, marks += e["mark"].get<double>(), ++endings["mark"];
    } else {
      ++fouls, ++endings[e["reason"].get<std::string>()];
    }
  }
  const int n = static_cast<int>(seeds.size());
  return {{"attempts", n},
          {"valid_rate", static_cast<double>(valid) / n},
          {"valid_ci95", wilson_95(valid, n)},
          {"foul_rate", static_cast<double>(fouls) / n},
          {"foul_ci95", wilson_95(fouls, n)},
          {"mean_mark_m", valid ? marks / valid : 0.0},
          {"endings", endings}};
}

// High jumps from the start mark, the first attempt's decision at each of `heights` (paper: the
// seed's episode, one try; official: the first of three tries at the competition's first height).
nlohmann::json high_jumps(const std::string& policy, const std::vector<std::uint64_t>& seeds,
                          const std::string& rules, const std::vector<double>& heights) {
  nlohmann::json by_height = nlohmann::json::object();
  for (const double height : heights) {
    int cleared = 0;
    std::map<std::string, int> endings;
    for (const std::uint64_t seed : seeds) {
      const nlohmann::json e =
          decision("high_jump", {{"rules", rules}, {"bar_height", height}}, seed, policy);
      const std::string end = e.is_null()              ? "undecided"
                              : e["call"] == "cleared" ? "cleared"
                                                       : e["reason"].get<std::string>();
      cleared += end == "cleared";
      ++endings[end];
    }
    const int n = static_cast<int>(seeds.size());
    char key[16];
    std::snprintf(key, sizeof key, "%.1f", height);
    by_height[key] = {{"attempts", n},
                      {"leap_over_rate", static_cast<double>(cleared) / n},
                      {"leap_over_ci95", wilson_95(cleared, n)},
                      {"endings", endings}};
  }
  return by_height;
}

// Golf, official: one hole per seed, the distance drawn from the seed (U[1, 3] m: the scripted
// putter was tuned on 1, 1.5, 2, 2.5 and 3 m only), 20 s and at most 6 strokes to hole out.
// Hit = a stroke was played; the first putt's end (holed or at rest) and the hole's; fell = the
// athlete fell during the hole (the referee's fall event).
nlohmann::json golf_holes(const std::string& policy, const std::vector<std::uint64_t>& seeds,
                          const std::string& address) {
  int hit = 0, holed = 0, holed_first = 0, strokes = 0, fell = 0;
  double first_miss = 0;
  for (const std::uint64_t seed : seeds) {
    std::mt19937_64 draw(seed);
    nlohmann::json options = {
        {"rules", "official"}, {"hole_s", 20}, {"max_strokes", 6}, {"address", address}};
    options["distance"] = std::uniform_real_distribution<double>(1.0, 3.0)(draw);
    bool first = true, in = false, down = false;
    int taken = 0;
    play_in_process("golf", {"solo", seed, 0.0, options}, {policy},
                    [&](const sports::SportMatch& m) {
                      for (const auto& e : m.outcome().info["events"]) {
                        const std::string call = e["call"];
                        if (call == "stroke") taken = e["stroke"];
                        if (call == "holed") in = true;
                        if (call == "fall") down = true;
                        if (first && (call == "holed" || call == "at_rest")) {
                          first = false;
                          holed_first += call == "holed";
                          first_miss += call == "holed" ? 0.0 : e["distance"].get<double>();
                        }
                      }
                    });
    hit += taken > 0, holed += in, strokes += in ? taken : 0, fell += down;
  }
  const int n = static_cast<int>(seeds.size());
  return {{"holes", n},
          {"hit_rate", static_cast<double>(hit) / n},
          {"hit_ci95", wilson_95(hit, n)},
          {"first_putt_holed_rate", static_cast<double>(holed_first) / n},
          {"first_putt_holed_ci95", wilson_95(holed_first, n)},
          {"mean_first_putt_distance_m", hit ? first_miss / hit : 0.0},
          {"holed_rate", static_cast<double>(holed) / n},
          {"holed_ci95", wilson_95(holed, n)},
          {"mean_strokes_when_holed", holed ? static_cast<double>(strokes) / holed : 0.0},
          {"fell_rate", static_cast<double>(fell) / n},
          {"fell_ci95", wilson_95(fell, n)},
          {"address", address}};
}

// Golf, paper: the seed's shot and its metrics (hit = its contact; stop distance; success =
// stopped within 1 m of the target).
nlohmann::json golf_shots(const std::string& policy, const std::vector<std::uint64_t>& seeds) {
  int hit = 0, stopped = 0, success = 0;
  double stop = 0;
  std::map<std::string, int> endings;
  for (const std::uint64_t seed : seeds) {
    const nlohmann::json e = decision("golf", {}, seed, policy);
    if (e.is_null()) {
      ++endings["undecided"];
      continue;
    }
    ++endings[e["reason"].get<std::string>()];
    hit += e["hit"].get<bool>(), success += e["success"].get<bool>();
    if (e["reason"] == "ball_stopped") ++stopped, stop += e["stop_distance"].get<double>();
  }
  const int n = static_cast<int>(seeds.size());
  return {{"shots", n},
          {"hit_rate", static_cast<double>(hit) / n},
          {"hit_ci95", wilson_95(hit, n)},
          {"mean_stop_distance_m", stopped ? stop / stopped : 0.0},
          {"success_rate", static_cast<double>(success) / n},
          {"success_ci95", wilson_95(success, n)},
          {"endings", endings}};
}

}  // namespace

nlohmann::json run_athletics_bench(const AthleticsBenchOptions& o) {
  const std::string named = named_or_evaluation_seeds(o.seeds, o.episodes);
  const auto seeds = episode_seeds(named, 0);
  nlohmann::json report = {{"seeds", named}};
  auto wanted = [&o](const std::string& event) {
    return std::find(o.events.begin(), o.events.end(), event) != o.events.end();
  };
  for (const auto& policy : o.policies) {
    if (wanted("long_jump")) report["long_jump"][policy] = long_jumps(policy, seeds, 20.0);
    if (wanted("standing_long_jump"))
      report["standing_long_jump"][policy] = long_jumps(policy, seeds, kStandingRunUp);
    if (wanted("high_jump"))
      report["high_jump"][policy] = high_jumps(policy, seeds, "paper", {0.5, 1.0, 1.5, 2.0});
    if (wanted("high_jump_official"))
      report["high_jump_official"][policy] = high_jumps(policy, seeds, "official", {0.5, 1.0});
    if (wanted("javelin")) report["javelin"][policy] = javelin_throws(policy, seeds);
    if (wanted("hurdles"))
      for (const auto& [name, options] : hurdles_rule_sets())
        report["hurdles"][name][policy] = hurdles_races(policy, seeds, options);
    if (wanted("golf")) report["golf_paper"][policy] = golf_shots(policy, seeds);
  }
  if (wanted("javelin")) report["javelin_flight"] = javelin_flight(seeds);
  if (wanted("golf")) {
    std::vector<std::string> golfers = o.policies;
    if (std::find(golfers.begin(), golfers.end(), "scripted") == golfers.end())
      golfers.push_back("scripted");  // golf has a scripted putter
    for (const auto& policy : golfers)
      report["golf"][policy] = golf_holes(policy, seeds, o.golf_address);
  }
  if (o.speed) {
    const core::ModelSpec& smpl = core::load_humanoid(core::HumanoidKind::Smpl);
    for (const char* sport : {"long_jump", "high_jump", "golf"})
      if (wanted(sport))
        report["speed_competition_8"][sport] =
            speed_vs_bare(sport, smpl, o.seconds, o.repeats, 45, "competition_8");
    if (wanted("hurdles"))
      report["speed_competition_8"]["hurdles"] = speed_vs_bare(
          "hurdles", smpl, o.seconds, o.repeats, 45, "competition_8", {{"rules", "official"}});
    // The javelin's SMPL-X athletes, over the first 15 ticks (the javelins still held).
    if (wanted("javelin"))
      report["speed_competition_8"]["javelin"] =
          speed_vs_bare("javelin", core::load_humanoid(core::HumanoidKind::SmplX), o.seconds,
                        o.repeats, 15, "competition_8");
  }
  return report;
}

void print_athletics_report(const nlohmann::json& r) {
  std::printf("seeds %s\n", r["seeds"].get<std::string>().c_str());
  static const nlohmann::json kNone = nlohmann::json::object();  // an event not measured
  for (const char* key : {"long_jump", "standing_long_jump"}) {
    if (!r.contains(key)) continue;
    std::printf("%s (official, one attempt, run-up %.1f m):\n", key,
                std::string(key) == "long_jump" ? 20.0 : kStandingRunUp);
    for (const auto& [policy, v] : r[key].items())
      std::printf("  %-8s valid %.2f [%.2f, %.2f]  fouls %.2f [%.2f, %.2f]  mean mark %.2f m  %s\n",
                  policy.c_str(), v["valid_rate"].get<double>(), v["valid_ci95"][0].get<double>(),
                  v["valid_ci95"][1].get<double>(), v["foul_rate"].get<double>(),
                  v["foul_ci95"][0].get<double>(), v["foul_ci95"][1].get<double>(),
                  v["mean_mark_m"].get<double>(), v["endings"].dump().c_str());
  }
  for (const char* key : {"high_jump", "high_jump_official"}) {
    if (!r.contains(key)) continue;
    std::printf(std::string(key) == "high_jump"
                    ? "high jump (paper, one try): leap-over rate per bar height\n"
                    : "high jump (official, first try at the first height): clearance rate\n");
    for (const auto& [policy, heights] : r[key].items())
      for (const auto& [h, v] : heights.items())
        std::printf("  %-8s %s m  %.2f [%.2f, %.2f]  %s\n", policy.c_str(), h.c_str(),
                    v["leap_over_rate"].get<double>(), v["leap_over_ci95"][0].get<double>(),
                    v["leap_over_ci95"][1].get<double>(), v["endings"].dump().c_str());
  }
  print_javelin_report(r);
  if (r.contains("hurdles")) print_hurdles_report(r["hurdles"]);
  if (r.contains("golf")) {
    std::printf("golf (official, one hole from U[1, 3] m, 20 s, max 6 strokes, address: %s):\n",
                r["golf"].begin()->at("address").get<std::string>().c_str());
    for (const auto& [policy, v] : r["golf"].items())
      std::printf(
          "  %-8s hit %.2f [%.2f, %.2f]  first putt holed %.2f [%.2f, %.2f], mean %.2f m from the "
          "hole  holed %.2f [%.2f, %.2f] in %.2f strokes  fell %.2f [%.2f, %.2f]\n",
          policy.c_str(), v["hit_rate"].get<double>(), v["hit_ci95"][0].get<double>(),
          v["hit_ci95"][1].get<double>(), v["first_putt_holed_rate"].get<double>(),
          v["first_putt_holed_ci95"][0].get<double>(), v["first_putt_holed_ci95"][1].get<double>(),
          v["mean_first_putt_distance_m"].get<double>(), v["holed_rate"].get<double>(),
          v["holed_ci95"][0].get<double>(), v["holed_ci95"][1].get<double>(),
          v["mean_strokes_when_holed"].get<double>(), v["fell_rate"].get<double>(),
          v["fell_ci95"][0].get<double>(), v["fell_ci95"][1].get<double>());
    std::printf("golf (paper, the seed's shot):\n");
    for (const auto& [policy, v] : r["golf_paper"].items())
      std::printf("  %-8s hit %.2f [%.2f, %.2f]  success %.2f [%.2f, %.2f]  mean stop %.2f m  %s\n",
                  policy.c_str(), v["hit_rate"].get<double>(), v["hit_ci95"][0].get<double>(),
                  v["hit_ci95"][1].get<double>(), v["success_rate"].get<double>(),
                  v["success_ci95"][0].get<double>(), v["success_ci95"][1].get<double>(),
                  v["mean_stop_distance_m"].get<double>(), v["endings"].dump().c_str());
  }
  if (!r.contains("speed_competition_8")) return;
  for (const auto& [sport, v] : r["speed_competition_8"].items())
    std::printf(
        "%s competition_8 ticks/s on one core (zero actions, first %d ticks): match %.0f, bare "
        "physics of 8 humanoids %.0f (ratio %.2f)\n",
        sport.c_str(), v["ticks_per_match"].get<int>(), v["match_ticks_per_s"].get<double>(),
        v["bare_physics_ticks_per_s"].get<double>(), v["ratio"].get<double>());
}

}  // namespace olympics::bench
