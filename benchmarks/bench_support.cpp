#include "bench_support.h"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "core/control_rate.h"
#include "core/humanoid_scene.h"
#include "policies.h"
#include "registry.h"

namespace olympics::bench {
namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}
}  // namespace

client::MatchInfo in_process_match_info(const std::string& sport, const std::string& mode,
                                        const sports::SportMatch& match) {
  return {sport, mode, core::kControlDt,
          client::ObservationLayout::from_blocks(match.layout().observation), match.action_size()};
}

std::unique_ptr<sports::SportMatch> play_in_process(
    const std::string& sport, const sports::MatchSettings& settings,
    const std::vector<std::string>& policies,
    const std::function<void(const sports::SportMatch&)>& after_tick) {
  return play_in_process_until(sport, settings, policies, [&](const sports::SportMatch& m) {
    if (after_tick) after_tick(m);
    return false;
  });
}

std::unique_ptr<sports::SportMatch> play_in_process_until(
    const std::string& sport, const sports::MatchSettings& settings,
    const std::vector<std::string>& policies,
    const std::function<bool(const sports::SportMatch&)>& done) {
  auto match = sports::sport_or_throw(sport).create(settings);
  const int n = match->slot_count();
  std::vector<std::unique_ptr<client::Policy>> players;
  for (int s = 0; s < n; ++s) {
    players.push_back(client::make_policy(policies[s], 100 * settings.seed + s));
    players.back()->start(in_process_match_info(sport, settings.mode, *match));
  }
  std::vector<std::vector<float>> obs(n, std::vector<float>(match->obs_size())),
      act(n, std::vector<float>(match->action_size()));
  std::vector<std::span<const float>> actions(act.begin(), act.end());
  while (!match->outcome().match_over) {
    for (int s = 0; s < n; ++s) {
      match->observe(s, obs[s]);
      players[s]->act(obs[s], act[s]);
    }
    match->step(actions);
    if (done(*match)) break;
  }
  return match;
}

std::string named_or_evaluation_seeds(const std::string& named, int n) {
  if (!named.empty()) return named;
  if (n <= 0) return "";  // none asked for (e.g. --matches 0)
  return std::to_string(kFirstEvaluationSeed) + "-" + std::to_string(kFirstEvaluationSeed + n - 1);
}

std::vector<std::uint64_t> episode_seeds(const std::string& named, int n) {
  std::vector<std::uint64_t> seeds;
  if (named.empty()) {
    for (int k = 1; k <= n; ++k) seeds.push_back(static_cast<std::uint64_t>(k));
    return seeds;
  }
  auto refuse = [&](const std::string& part) {
    throw std::invalid_argument("seeds \"" + named + "\": \"" + part +
                                "\" is not a seed or a range like 5001-5500");
  };
  std::size_t start = 0;
  while (start <= named.size()) {
    const std::size_t comma = std::min(named.find(',', start), named.size());
    const std::string part = named.substr(start, comma - start);
    const std::size_t dash = part.find('-');
    try {
      std::size_t used = 0;
      const std::uint64_t first = std::stoull(part.substr(0, dash), &used);
      if (used != std::min(dash, part.size())) refuse(part);
      std::uint64_t last = first;
      if (dash != std::string::npos) {
        last = std::stoull(part.substr(dash + 1), &used);
        if (used != part.size() - dash - 1 || last < first) refuse(part);
      }
      for (std::uint64_t s = first; s <= last; ++s) seeds.push_back(s);
    } catch (const std::logic_error&) {  // stoull's invalid_argument and out_of_range
      refuse(part);
    }
    start = comma + 1;
  }
  return seeds;
}

std::array<double, 2> wilson_95(int hits, int n) {
  if (n <= 0) return {0, 1};
  constexpr double z = 1.959964;
  const double p = static_cast<double>(hits) / n, z2 = z * z / n;
  const double centre = (p + z2 / 2) / (1 + z2);
  const double half = z * std::sqrt(p * (1 - p) / n + z * z / (4.0 * n * n)) / (1 + z2);
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

std::array<double, 3> ratio_95(const std::vector<double>& counts,
                               const std::vector<double>& exposure) {
  const double n = static_cast<double>(counts.size());
  double c = 0, e = 0;
  for (size_t k = 0; k < counts.size(); ++k) c += counts[k], e += exposure[k];
  const double rate = e > 0 ? c / e : 0;
  double var = 0;
  for (size_t k = 0; k < counts.size(); ++k) var += std::pow(counts[k] - rate * exposure[k], 2);
  const double half = n > 1 && e > 0 ? 1.959964 * std::sqrt(var / (n - 1) / n) / (e / n) : 0;
  return {rate, std::max(0.0, rate - half), rate + half};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double match_ticks_per_s(const std::string& sport, double seconds, int ticks_per_match,
                         const std::string& mode, const nlohmann::json& options) {
  const auto& s = sports::sport_or_throw(sport);
  const int slots = s.modes().at(mode).slot_count();
  std::vector<float> act;
  std::vector<std::span<const float>> actions;
  std::vector<float> obs;
  long ticks = 0;
  double stepping = 0;
  std::uint64_t seed = 1;
  while (stepping < seconds) {
    auto match = s.create({mode, seed++, 60.0, options});
    obs.resize(match->obs_size());
    act.assign(match->action_size(), 0.0f);
    actions.assign(slots, std::span<const float>(act));
    const auto start = Clock::now();
    for (int t = 0; t < ticks_per_match && !match->outcome().match_over; ++t, ++ticks) {
      for (int slot = 0; slot < slots; ++slot) match->observe(slot, obs);
      match->step(actions);
    }
    stepping += since(start);
  }
  return ticks / stepping;
}

double bare_ticks_per_s(const core::ModelSpec& spec, double seconds, int ticks_per_match,
                        int players) {
  std::vector<float> act(spec.dof_count(), 0.0f);
  long ticks = 0;
  double stepping = 0;
  while (stepping < seconds) {
    core::HumanoidScene scene;
    for (int i = 0; i < players; ++i)  // facing each other in pairs, 3 m between pairs
      scene.add_humanoid(spec, {{i % 2 == 0 ? -2.0 : 2.0, 3.0 * (i / 2), 0}, i % 2 ? M_PI : 0});
    const auto start = Clock::now();
    for (int t = 0; t < ticks_per_match; ++t, ++ticks) {
      for (int i = 0; i < players; ++i) scene.set_action(i, act);
      scene.tick();
    }
    stepping += since(start);
  }
  return ticks / stepping;
}

nlohmann::json speed_vs_bare(const std::string& sport, const core::ModelSpec& players,
                             double seconds, int repeats, int ticks, const std::string& mode,
                             const nlohmann::json& options) {
  const int count = sports::sport_or_throw(sport).modes().at(mode).slot_count();
  std::vector<double> match, bare, ratio;
  for (int i = 0; i < repeats; ++i) {
    match.push_back(match_ticks_per_s(sport, seconds, ticks, mode, options));
    bare.push_back(bare_ticks_per_s(players, seconds, ticks, count));
    ratio.push_back(match.back() / bare.back());
  }
  return {{"match_ticks_per_s", median(match)},
          {"bare_physics_ticks_per_s", median(bare)},
          {"ratio", median(ratio)},
          {"ticks_per_match", ticks}};
}

namespace {
double this_thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + t.tv_nsec * 1e-9;
}
}  // namespace

TickRate sandbox_tick_rate(int matches, double seconds) {
  const sports::Sport& sandbox = sports::sport_or_throw("sandbox");
  std::vector<std::unique_ptr<sports::SportMatch>> games;
  for (int m = 0; m < matches; ++m)
    games.push_back(sandbox.create({"1v1", static_cast<std::uint64_t>(m), 20}));
  std::vector<float> zero(69, 0.0f);
  std::vector<std::span<const float>> actions(2, zero);
  long ticks = 0;
  auto start = Clock::now();
  const double cpu_start = this_thread_cpu_seconds();
  double elapsed = 0;
  std::uint64_t next_seed = matches;
  while (elapsed < seconds) {
    for (auto& g : games) {
      // Observations are part of a tick's cost on the server too.
      std::vector<float> obs(g->obs_size());
      for (int s = 0; s < 2; ++s) g->observe(s, obs);
      g->step(actions);
      ++ticks;
      if (g->outcome().match_over) g = sandbox.create({"1v1", next_seed++, 20});
    }
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  }
  return {ticks / elapsed, ticks / (this_thread_cpu_seconds() - cpu_start)};
}

double sum_over_threads(int threads, const std::function<double(int)>& rate) {
  std::vector<double> rates(threads);
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back([&, t] { rates[t] = rate(t); });
  for (auto& th : pool) th.join();
  double sum = 0;
  for (double r : rates) sum += r;
  return sum;
}

}  // namespace olympics::bench
