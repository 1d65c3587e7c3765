// Basketball figures, the yardsticks learned players must beat: free throws with fixed seeds
// (by default the evaluation seeds from 5001) by policy (the fraction made, how they ended), the
// scripted shooter's from nearer lines (it aims by the ballistic solution), and ticks/s of 1v1 and
// 2v2 (two and four SMPL-X humanoids, the court and the ball) against the bare physics of as many
// SMPL-X humanoids, measured interleaved.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace olympics::bench {

struct BasketballBenchOptions {
  int throws = 100;  // free throws per policy (evaluation seeds 5001..5000+N) when `seeds` is empty
  std::string seeds;  // or the seeds named: "5001-5500,7001-7200" (docs/figures.md)
  std::vector<std::string> policies = {"scripted", "zero", "random"};
  std::vector<double> scripted_distances = {3.6, 4.0, 4.3};  // free-throw lines nearer than 4.6 m
  double seconds = 2;                                        // wall seconds per speed measurement
  int repeats = 3;
  bool speed = true;
  bool per_throw = false;   // each scripted throw's release in the report
  bool free_throws = true;  // false: only the scripted 1v1 games (if any)
  // Scripted 1v1 games (both slots the scripted team player), one per seed of `game_seeds`
  // ("400001-400024"; empty: none), each `game_s` seconds of play.
  std::string game_seeds;
  double game_s = 600;
  // The standing dribble (basketball_dribble_bench.h), one episode per seed of `dribble_seeds`
  // (empty: none), `dribble_s` seconds each.
  std::string dribble_seeds;
  double dribble_s = 10;
  bool per_dribble = false;  // each episode in the report
};

nlohmann::json run_basketball_bench(const BasketballBenchOptions& options);
void print_basketball_report(const nlohmann::json& report);

}  // namespace olympics::bench
