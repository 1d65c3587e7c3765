// Tennis and table tennis figures (docs/racket-sports.md): the scripted baseline's play and the
// speed of a match against bare physics.
//
// - ball return, per policy: balls fed and returned in (the seed's hit: the return lands on the
//   other side) with a 95% interval, balls touched, returns in per episode (the seed's "average
//   hits per episode", beside SMPLOlympics' 1.83 for table tennis), falls per minute;
// - 1v1, scripted against scripted, in the standard short format (table tennis best of 3 games
//   to 11; tennis one set with a tie-break): strokes per point (median, p90, longest), the share
//   of matches decided by score rather than the time limit, falls per minute;
// - 2v2 (--doubles N), the same figures for doubles, every player scripted;
// - serves (--serves N): the scripted player's first serve of N 1v1s and of N 2v2s, in / fault
//   (by reason) / let;
// - 1v1 ticks/s on one core against the same equipped humanoids stepping with nothing else.
// Every figure is on seeds no tuning used: the scripted player was tuned on ball-return seeds
// 1-200, so episodes here start at 100001 unless told otherwise.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace olympics::bench {

struct RacketBenchOptions {
  int balls = 1000;    // ball return: episodes are played until this many balls were fed
  int episodes = 0;    // ...or exactly this many episodes, when it is set
  int matches = 20;    // 1v1 matches per sport (0: none)
  int doubles = 0;     // 2v2 matches per sport, every player scripted (0: none)
  int serves = 0;      // scripted serves per sport and mode (`start: "serve"`), one match per seed
  std::string seeds;   // first seeds, e.g. "100001-200000" (docs/figures.md); empty: from 100001
  double seconds = 2;  // wall seconds per speed measurement
  int repeats = 3;     // interleaved repeats (median reported)
  // Ball-return players: any olympics-agent policy (mlp:FILE measures a trained snapshot; the
  // trainer's own seeds start at 10^6).
  std::vector<std::string> policies = {"scripted", "zero"};
  std::vector<std::string> sports = {"tennis", "table_tennis"};
  bool speed = true;  // also the 1v1 ticks/s figure
};

nlohmann::json run_racket_bench(const RacketBenchOptions& options);
void print_racket_report(const nlohmann::json& report);

}  // namespace olympics::bench
