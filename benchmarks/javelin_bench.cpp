#include "javelin_bench.h"

#include <cstdio>
#include <map>
#include <random>

#include "bench_support.h"
#include "javelin/javelin_flight.h"

namespace olympics::bench {

nlohmann::json javelin_throws(const std::string& policy, const std::vector<std::uint64_t>& seeds) {
  int valid = 0;
  double marks = 0;
  std::map<std::string, int> endings;
  const nlohmann::json options = {{"rules", "official"}, {"run_up", 2.0}, {"attempts", 1}};
  for (const std::uint64_t seed : seeds) {
    nlohmann::json decided;
    play_in_process("javelin", {"solo", seed, 0.0, options}, {policy},
                    [&](const sports::SportMatch& m) {
                      for (const auto& e : m.outcome().info["events"])
                        if (decided.is_null() && (e["call"] == "mark" || e["call"] == "foul"))
                          decided = e;
                    });
    if (decided.is_null()) {
      ++endings["undecided"];
    } else if (decided["call"] == "mark") {
      ++valid, marks += decided["mark"].get<double>(), ++endings["mark"];
    } else {
      ++endings[decided["reason"].get<std::string>()];
    }
  }
  const int n = static_cast<int>(seeds.size());
  return {{"attempts", n},
          {"valid_rate", static_cast<double>(valid) / n},
          {"valid_ci95", wilson_95(valid, n)},
          {"mean_valid_mark_m", valid ? marks / valid : 0.0},
          {"endings", endings}};
}

nlohmann::json javelin_flight(const std::vector<std::uint64_t>& seeds) {
  using namespace sports::javelin;
  int tip_first_air = 0, tip_first_vacuum = 0;
  double x_air = 0, x_vacuum = 0;
  for (const std::uint64_t seed : seeds) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    JavelinRelease r;
    r.speed = 15 + 15 * u(rng);
    r.angle_deg = 25 + 15 * u(rng);
    r.attitude_deg = r.angle_deg - 5 + 15 * u(rng);
    r.pitch_rate = -0.5 + u(rng);
    const JavelinLanding air = fly(official_javelin(), true, r);
    const JavelinLanding vacuum = fly(official_javelin(), false, r);
    tip_first_air += air.tip_first;
    tip_first_vacuum += vacuum.tip_first;
    x_air += air.first_touch.x();
    x_vacuum += vacuum.first_touch.x();
  }
  const int n = static_cast<int>(seeds.size());
  auto rate = [n](int hits) {
    return nlohmann::json{{"tip_first_rate", static_cast<double>(hits) / n},
                          {"tip_first_ci95", wilson_95(hits, n)}};
  };
  nlohmann::json air = rate(tip_first_air), vacuum = rate(tip_first_vacuum);
  air["mean_first_touch_x_m"] = x_air / n;
  vacuum["mean_first_touch_x_m"] = x_vacuum / n;
  return {{"throws", n}, {"crossflow", air}, {"none", vacuum}};
}

void print_javelin_report(const nlohmann::json& r) {
  if (r.contains("javelin")) {
    std::printf("javelin (official, standing throw 2 m behind the arc, one attempt):\n");
    for (const auto& [policy, v] : r["javelin"].items())
      std::printf("  %-8s valid %.2f [%.2f, %.2f] of %d  mean valid mark %.2f m  %s\n",
                  policy.c_str(), v["valid_rate"].get<double>(), v["valid_ci95"][0].get<double>(),
                  v["valid_ci95"][1].get<double>(), v["attempts"].get<int>(),
                  v["mean_valid_mark_m"].get<double>(), v["endings"].dump().c_str());
  }
  if (r.contains("javelin_flight")) {
    const auto& f = r["javelin_flight"];
    std::printf("javelin flight (800 g, %d releases, 15-30 m/s): tip first\n",
                f["throws"].get<int>());
    for (const char* air : {"crossflow", "none"})
      std::printf("  air %-9s %.2f [%.2f, %.2f]  mean first touch x %.1f m\n", air,
                  f[air]["tip_first_rate"].get<double>(), f[air]["tip_first_ci95"][0].get<double>(),
                  f[air]["tip_first_ci95"][1].get<double>(),
                  f[air]["mean_first_touch_x_m"].get<double>());
  }
}

}  // namespace olympics::bench
