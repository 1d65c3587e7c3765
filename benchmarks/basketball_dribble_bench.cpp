#include "basketball_dribble_bench.h"

#include <algorithm>
#include <string>

#include "basketball/basketball_match.h"
#include "bench_support.h"
#include "registry.h"
#include "scripted_basketball_dribble.h"
#include "scripted_basketball_team.h"

namespace olympics::bench {
namespace {
constexpr double kPresent_s = 0.5;  // the check ball presented (`present_s`'s default)
}  // namespace

nlohmann::json scripted_dribbles(const std::vector<std::uint64_t>& seeds, double seconds,
                                 bool per_episode) {
  std::vector<int> counts;
  std::vector<double> fell_at_s;  // of the episodes with a fall
  int kept = 0, falls = 0, one = 0, two = 0, three = 0;
  nlohmann::json episodes = nlohmann::json::array();
  for (const std::uint64_t seed : seeds) {
    auto m = sports::sport_or_throw("basketball").create({"1v1", seed, 0.0, {}});
    const auto& match = dynamic_cast<const sports::basketball::BasketballMatch&>(*m);
    const client::MatchInfo info = in_process_match_info("basketball", "1v1", *m);
    const int dribbler = match.referee().possession();  // 1v1: slot = side
    client::ScriptedDribbler dribbling;
    client::ScriptedBasketballTeamPlayer standing;
    client::Policy* players[2];
    players[dribbler] = &dribbling, players[1 - dribbler] = &standing;
    for (auto* p : players) p->start(info);
    client::DribbleTally tally;
    bool fell = false;
    double fell_at = -1, lost_at = -1;
    std::string fell_body;  // the body whose touch (or height) the referee called the fall on
    std::vector<float> obs[2], act[2];
    const double until = kPresent_s + seconds;
    while (!m->outcome().match_over && m->tick() * m->control_dt() < until) {
      for (int s = 0; s < 2; ++s) {
        obs[s].resize(m->obs_size()), act[s].resize(m->action_size());
        m->observe(s, obs[s]);
        players[s]->act(obs[s], act[s]);
      }
      m->step({std::span<const float>(act[0]), std::span<const float>(act[1])});
      const nlohmann::json& events = m->outcome().info;
      if (events.contains("events"))
        for (const auto& e : events["events"]) {
          const std::string call = e.value("call", "");
          if (call == "fall" && e.value("slot", -1) == dribbler) {
            if (!fell) fell_at = m->tick() * m->control_dt(), fell_body = e.value("body", "");
            fell = true, tally.lose();
          }
          if (call == "restart") tally.lose();  // out, shot clock: play stopped
        }
      const Eigen::Vector3d ball = match.ball().position();
      const Eigen::Vector3d root = match.scene().humanoid(dribbler).body_state(0).position;
      tally.tick(ball.z(), match.ball().velocity().z(), (ball - root).head<2>().norm());
      if (tally.lost() && lost_at < 0) lost_at = m->tick() * m->control_dt();
    }
    counts.push_back(tally.dribbles());
    one += tally.dribbles() >= 1, two += tally.dribbles() >= 2, three += tally.dribbles() >= 3;
    if (fell) fell_at_s.push_back(fell_at);
    kept += !tally.lost();
    falls += fell;
    if (per_episode)
      episodes.push_back({{"seed", seed},
                          {"dribbles", tally.dribbles()},
                          {"kept", !tally.lost()},
                          {"fell", fell},
                          {"fell_at_s", fell_at},
                          {"fell_body", fell_body},
                          {"lost_at_s", lost_at},
                          {"push_speed", dribbling.dribble().push_speed()}});
  }
  std::vector<int> sorted = counts;
  std::sort(sorted.begin(), sorted.end());
  const int n = static_cast<int>(sorted.size());
  auto quantile = [&](double q) { return n == 0 ? 0 : sorted[static_cast<size_t>(q * (n - 1))]; };
  // When the falls came (s from the match's start, the presentation included): p10, median, p90.
  std::sort(fell_at_s.begin(), fell_at_s.end());
  nlohmann::json fell_at = nlohmann::json::array();
  for (const double q : {0.1, 0.5, 0.9})
    if (!fell_at_s.empty())
      fell_at.push_back(fell_at_s[static_cast<size_t>(q * (fell_at_s.size() - 1))]);
  nlohmann::json r = {{"episodes", n},
                      {"seconds", seconds},
                      {"dribbles_median", quantile(0.5)},
                      {"dribbles_p10", quantile(0.1)},
                      {"kept_share", n ? static_cast<double>(kept) / n : 0.0},
                      {"kept_ci95", wilson_95(kept, std::max(n, 1))},
                      {"one_or_more", one},
                      {"one_or_more_ci95", wilson_95(one, std::max(n, 1))},
                      {"two_or_more", two},
                      {"two_or_more_ci95", wilson_95(two, std::max(n, 1))},
                      {"three_or_more", three},
                      {"three_or_more_ci95", wilson_95(three, std::max(n, 1))},
                      {"falls", falls},
                      {"falls_ci95", wilson_95(falls, std::max(n, 1))},
                      {"fell_at_s_p10_median_p90", fell_at}};
  if (per_episode) r["per_episode"] = episodes;
  return r;
}

}  // namespace olympics::bench
