// Pieces the benchmarks share: what a policy is told of an in-process match, medians, and the
// speed of a sport's 1v1 against the bare physics of the same humanoids.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/model_spec.h"
#include "match_info.h"
#include "sport.h"

namespace olympics::bench {

// What a policy is told of a match played in process (the server tells remote clients the same
// through match_created_t).
client::MatchInfo in_process_match_info(const std::string& sport, const std::string& mode,
                                        const sports::SportMatch& match);

// Plays a match in process to its end, one policy per slot (client::make_policy's names, seeded
// 100 * seed + slot), calling `after_tick` (if any) after every tick; the match as it ended.
std::unique_ptr<sports::SportMatch> play_in_process(
    const std::string& sport, const sports::MatchSettings& settings,
    const std::vector<std::string>& policies,
    const std::function<void(const sports::SportMatch&)>& after_tick = {});
// The same, stopped early once `done` (asked after every tick) says so.
std::unique_ptr<sports::SportMatch> play_in_process_until(
    const std::string& sport, const sports::MatchSettings& settings,
    const std::vector<std::string>& policies,
    const std::function<bool(const sports::SportMatch&)>& done);

double median(std::vector<double> v);

// Episode seeds for a figure (docs/figures.md): "5001-5500,7001-7200" (ranges and single seeds,
// comma-separated), or empty for 1..n. Throws std::invalid_argument saying what was wrong.
std::vector<std::uint64_t> episode_seeds(const std::string& named, int n);
// The project's evaluation seeds start here (docs/figures.md): no scripted player was tuned on
// them, so a figure a bench reports by default is on seeds no tuning used.
constexpr std::uint64_t kFirstEvaluationSeed = 5001;
// The seeds a bench plays, as it reports them: the ones named, or n evaluation seeds
// ("5001-5100" for n = 100; "" for none).
std::string named_or_evaluation_seeds(const std::string& named, int n);
// The Wilson score 95% interval of a rate: `hits` of `n` episodes.
std::array<double, 2> wilson_95(int hits, int n);
// A rate over episodes of different lengths, sum(counts) / sum(exposure) (e.g. falls per
// player-minute), with its 95% interval by the delta method over episodes (ratio estimator):
// {rate, low, high}.
std::array<double, 3> ratio_95(const std::vector<double>& counts,
                               const std::vector<double>& exposure);

// The sum of `rate(t)` run on `threads` threads at once (t = 0..threads-1): an aggregate rate.
double sum_over_threads(int threads, const std::function<double(int)>& rate);

// Sandbox 1v1 matches (`matches` of them, round robin), zero actions, observed and stepped back
// to back on the calling thread for `seconds`: ticks per wall second, and per CPU second of the
// calling thread (what a core of its own would do, however loaded the machine is).
struct TickRate {
  double per_second = 0;
  double per_cpu_second = 0;
};
TickRate sandbox_tick_rate(int matches, double seconds);

// Ticks per second of a sport's mode (1v1 unless said) with zero actions, one core: matches of
// `ticks` each (or until one ends), only the stepping timed.
double match_ticks_per_s(const std::string& sport, double seconds, int ticks,
                         const std::string& mode = "1v1",
                         const nlohmann::json& options = nlohmann::json::object());
// Likewise for `players` humanoids of `spec` with nothing else: no arena, referee or rewards.
double bare_ticks_per_s(const core::ModelSpec& spec, double seconds, int ticks, int players = 2);
// Both, interleaved `repeats` times so that drift hits both alike: medians and their ratio.
// `ticks` short enough that no player falls (1.5 s) keeps both doing the same physics: a match
// puts fallen players back on their marks, bare physics leaves them on the floor.
nlohmann::json speed_vs_bare(const std::string& sport, const core::ModelSpec& players,
                             double seconds, int repeats, int ticks,
                             const std::string& mode = "1v1",
                             const nlohmann::json& options = nlohmann::json::object());

}  // namespace olympics::bench
