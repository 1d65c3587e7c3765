#include "racket_bench.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "bench_support.h"
#include "core/humanoid_assets.h"
#include "racket/racket_equipment.h"
#include "registry.h"

namespace olympics::bench {
namespace {

constexpr std::uint64_t kFirstUnseenSeed = 100001;    // tuning used ball-return seeds 1-200
constexpr double kSmplOlympicsHitsPerEpisode = 1.83;  // its best table-tennis method (the paper)

// Seeds to draw from, in order: the named ones, or kFirstUnseenSeed on.
class SeedList {
 public:
  explicit SeedList(const std::string& named) {
    if (!named.empty()) seeds_ = episode_seeds(named, 0);
  }
  std::uint64_t next() {
    if (seeds_.empty()) return kFirstUnseenSeed + used_++;
    if (used_ >= seeds_.size())
      throw std::invalid_argument(
          "--seeds names " + std::to_string(seeds_.size()) +
          " seeds, too few for the balls or matches asked: name more seeds, or ask for fewer "
          "(--balls, --episodes, --matches, --doubles, --serves)");
    return seeds_[used_++];
  }
  std::string used() const {
    if (used_ == 0) return "none";
    const std::uint64_t first = seeds_.empty() ? kFirstUnseenSeed : seeds_.front();
    const std::uint64_t last = seeds_.empty() ? kFirstUnseenSeed + used_ - 1 : seeds_[used_ - 1];
    return std::to_string(first) + "-" + std::to_string(last) +
           (seeds_.empty() ? "" : " (of the named list)");
  }

 private:
  std::vector<std::uint64_t> seeds_;
  size_t used_ = 0;
};

nlohmann::json rate(int hits, int n) {
  const auto ci = wilson_95(hits, n);
  return {{"count", hits}, {"of", n}, {"rate", n ? double(hits) / n : 0.0}, {"ci95", ci}};
}

// The referee's calls of this tick.
const nlohmann::json& events(const sports::SportMatch& m) {
  static const nlohmann::json none = nlohmann::json::array();
  const auto& info = m.outcome().info;
  return info.contains("events") ? info["events"] : none;
}

nlohmann::json ball_return(const std::string& sport, const std::string& policy, int balls,
                           int episodes_asked, const std::string& named_seeds) {
  SeedList seeds(named_seeds);
  int episodes = 0, fed = 0, touched = 0, returns_in = 0, falls = 0;
  double seconds = 0;
  while (episodes_asked > 0 ? episodes < episodes_asked : fed < balls) {
    bool touched_this_ball = false;
    const auto match = play_in_process(sport, {"ball_return", seeds.next(), 60.0, {}}, {policy},
                                       [&](const sports::SportMatch& m) {
                                         for (const auto& ev : events(m)) {
                                           const std::string call = ev.value("call", "");
                                           if (call == "hit" && !touched_this_ball)
                                             touched_this_ball = true, ++touched;
                                           if (call == "return_in")
                                             ++returns_in, ++fed, touched_this_ball = false;
                                           if (call == "point") ++fed;
                                           if (call == "fall") ++falls;
                                         }
                                       });
    ++episodes;
    seconds += match->tick() * match->control_dt();
  }
  return {{"episodes", episodes},
          {"seeds", seeds.used()},
          {"balls", fed},
          {"returns_in", rate(returns_in, fed)},
          {"touched", rate(touched, fed)},
          {"returns_in_per_episode", double(returns_in) / episodes},
          {"smplolympics_hits_per_episode", kSmplOlympicsHitsPerEpisode},
          {"falls", falls},
          {"falls_per_minute", falls / (seconds / 60)},
          {"seconds_played", seconds}};
}

// Scripted against scripted ("1v1", or "2v2" with every player scripted) in the sport's standard
// short format.
nlohmann::json scripted_matches(const std::string& sport, const std::string& mode, int matches,
                                const std::string& named_seeds) {
  const nlohmann::json format = sport == "table_tennis"
                                    ? nlohmann::json{{"games_to_win", 2}, {"points_per_game", 11}}
                                    : nlohmann::json{{"format", "sets"}, {"sets_to_win", 1}};
  SeedList seeds(named_seeds);
  std::vector<double> strokes;
  int by_score = 0, falls = 0, strokes_now = 0;
  nlohmann::json endings = nlohmann::json::object();  // what ended the points, by the call
  nlohmann::json endings_by_strokes = nlohmann::json::object();  // [strokes][call]
  double seconds = 0;
  for (int i = 0; i < matches; ++i) {
    const std::vector<std::string> players(mode == "2v2" ? 4 : 2, "scripted");
    const auto match = play_in_process(
        sport, {mode, seeds.next(), 0.0, format}, players, [&](const sports::SportMatch& m) {
          for (const auto& ev : events(m)) {
            const std::string call = ev.value("call", "");
            if (call == "hit") ++strokes_now;
            if (call == "fall") ++falls;
            if (call != "point") continue;
            strokes.push_back(strokes_now), strokes_now = 0;
            const std::string why = ev.value("reason", "");
            endings[why] = endings.value(why, 0) + 1;
            auto& at = endings_by_strokes[std::to_string(int(strokes.back()))];
            if (!at.is_object()) at = nlohmann::json::object();
            at[why] = at.value(why, 0) + 1;
          }
        });
    by_score += match->outcome().reason != "time_limit";
    seconds += match->tick() * match->control_dt();
  }
  std::sort(strokes.begin(), strokes.end());
  auto quantile = [&](double q) {
    return strokes.empty() ? 0.0
                           : strokes[std::min(strokes.size() - 1, size_t(q * strokes.size()))];
  };
  double mean = 0;
  std::vector<int> histogram;  // points by their strokes: [0], [1], ...
  for (double s : strokes) {
    mean += s;
    if (histogram.size() <= size_t(s)) histogram.resize(size_t(s) + 1, 0);
    ++histogram[size_t(s)];
  }
  return {{"matches", matches},
          {"seeds", seeds.used()},
          {"format", format},
          {"ended_by_score", rate(by_score, matches)},
          {"points", strokes.size()},
          {"strokes_per_point",
           {{"mean", strokes.empty() ? 0 : mean / strokes.size()},
            {"median", quantile(0.5)},
            {"p90", quantile(0.9)},
            {"longest", strokes.empty() ? 0.0 : strokes.back()},
            {"histogram", histogram}}},
          {"point_endings", endings},
          {"point_endings_by_strokes", endings_by_strokes},
          {"falls", falls},
          {"falls_per_minute", falls / (seconds / 60)},
          {"seconds_played", seconds}};
}

// The scripted player's serve (`start: "serve"`): the first serve of each seed's scripted 1v1 or
// 2v2 (every player scripted), as the referee calls it: in (`serve_in`), a `fault` (by its
// reason), a `let`, or neither before the point ended (e.g. a fall).
nlohmann::json first_serves(const std::string& sport, const std::string& mode, int serves,
                            const std::string& named_seeds) {
  SeedList seeds(named_seeds);
  int in = 0, faults = 0, lets = 0, other = 0;
  nlohmann::json fault_reasons = nlohmann::json::object();
  const std::vector<std::string> players(mode == "2v2" ? 4 : 2, "scripted");
  for (int i = 0; i < serves; ++i) {
    std::string call;  // how this seed's first serve was called
    play_in_process_until(sport, {mode, seeds.next(), 10.0, {{"start", "serve"}}}, players,
                          [&](const sports::SportMatch& m) {
                            for (const auto& ev : events(m)) {
                              const std::string c = ev.value("call", "");
                              if (c == "fault") {
                                const std::string why = ev.value("reason", "");
                                fault_reasons[why] = fault_reasons.value(why, 0) + 1;
                              }
                              if (c == "serve_in" || c == "fault" || c == "let" || c == "point")
                                call = c;
                              if (!call.empty()) return true;
                            }
                            return m.outcome().match_over;
                          });
    in += call == "serve_in", faults += call == "fault", lets += call == "let";
    other += call != "serve_in" && call != "fault" && call != "let";
  }
  return {{"mode", mode},           {"serves", serves}, {"seeds", seeds.used()},
          {"in", rate(in, serves)}, {"faults", faults}, {"fault_reasons", fault_reasons},
          {"lets", lets},           {"other", other}};
}

}  // namespace

nlohmann::json run_racket_bench(const RacketBenchOptions& o) {
  nlohmann::json report = {{"tuning_seeds", "ball return 1-200"},
                           {"sports", nlohmann::json::object()}};
  for (const std::string& sport : o.sports) {
    nlohmann::json& r = report["sports"][sport];
    for (const std::string& policy : o.policies)
      r["ball_return"][policy] = ball_return(sport, policy, o.balls, o.episodes, o.seeds);
    if (o.matches > 0) r["1v1"] = scripted_matches(sport, "1v1", o.matches, o.seeds);
    if (o.doubles > 0) r["2v2"] = scripted_matches(sport, "2v2", o.doubles, o.seeds);
    if (o.serves > 0) {  // "serve": 1v1 (the key it always had), "serve_2v2": doubles
      r["serve"] = first_serves(sport, "1v1", o.serves, o.seeds);
      r["serve_2v2"] = first_serves(sport, "2v2", o.serves, o.seeds);
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

namespace {
std::string percent(const nlohmann::json& r) {
  char s[96];
  std::snprintf(s, sizeof s, "%d of %d (%.1f%%, 95%% %.1f-%.1f%%)", r["count"].get<int>(),
                r["of"].get<int>(), 100 * r["rate"].get<double>(), 100 * r["ci95"][0].get<double>(),
                100 * r["ci95"][1].get<double>());
  return s;
}
}  // namespace

void print_racket_report(const nlohmann::json& report) {
  std::printf("(seeds unseen by tuning; tuning used %s)\n",
              report["tuning_seeds"].get<std::string>().c_str());
  for (const auto& [sport, r] : report["sports"].items()) {
    std::printf("%s\n", sport.c_str());
    for (const auto& [policy, b] : r["ball_return"].items()) {
      std::printf("  ball_return %-8s %d episodes (seeds %s): %d balls fed\n", policy.c_str(),
                  b["episodes"].get<int>(), b["seeds"].get<std::string>().c_str(),
                  b["balls"].get<int>());
      std::printf("    returns in %s; touched %s\n", percent(b["returns_in"]).c_str(),
                  percent(b["touched"]).c_str());
      std::printf(
          "    returns in per episode %.2f (SMPLOlympics' best: %.2f hits); %d falls, "
          "%.2f per minute\n",
          b["returns_in_per_episode"].get<double>(),
          b["smplolympics_hits_per_episode"].get<double>(), b["falls"].get<int>(),
          b["falls_per_minute"].get<double>());
    }
    for (const char* key : {"serve", "serve_2v2"}) {
      if (!r.contains(key)) continue;
      const auto& v = r[key];
      std::printf(
          "  serve (start: serve), the first of %d scripted %ss (seeds %s): in %s; %d faults %s, "
          "%d lets, %d other\n",
          v["serves"].get<int>(), v["mode"].get<std::string>().c_str(),
          v["seeds"].get<std::string>().c_str(), percent(v["in"]).c_str(), v["faults"].get<int>(),
          v["fault_reasons"].dump().c_str(), v["lets"].get<int>(), v["other"].get<int>());
    }
    for (const char* mode : {"1v1", "2v2"}) {
      if (!r.contains(mode)) continue;
      const auto& s = r[mode];
      const auto& k = s["strokes_per_point"];
      std::printf("  %s scripted x scripted, %d matches %s (seeds %s): ended by score %s\n", mode,
                  s["matches"].get<int>(), s["format"].dump().c_str(),
                  s["seeds"].get<std::string>().c_str(), percent(s["ended_by_score"]).c_str());
      std::printf(
          "    %d points; strokes per point mean %.2f, median %.0f, p90 %.0f, longest %.0f; "
          "%d falls, %.2f per minute\n",
          s["points"].get<int>(), k["mean"].get<double>(), k["median"].get<double>(),
          k["p90"].get<double>(), k["longest"].get<double>(), s["falls"].get<int>(),
          s["falls_per_minute"].get<double>());
      std::string endings;
      for (const auto& [why, n] : s["point_endings"].items())
        endings += (endings.empty() ? "" : ", ") + why + " " + std::to_string(n.get<int>());
      std::printf("    points ended by: %s\n", endings.c_str());
    }
    if (!r.contains("speed_1v1")) continue;
    const auto& s = r["speed_1v1"];
    std::printf("  1v1 ticks/s on one core: match %.0f, bare physics %.0f, ratio %.2f\n",
                s["match_ticks_per_s"].get<double>(), s["bare_physics_ticks_per_s"].get<double>(),
                s["ratio"].get<double>());
  }
}

}  // namespace olympics::bench
