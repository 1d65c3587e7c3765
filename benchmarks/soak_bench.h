// `olympics-bench soak`: one olympics-server process holding as many concurrent matches as the
// machine allows, for an hour (not in CI). In-process clients play scripted matches back to back
// (fencing, boxing, tennis, table tennis; both slots each) while an olympics-league process plays
// tournaments on the same server. Each client times its tick cycle (one observation to the
// next); a ramp adds matches until the p99 misses the budget, the soak holds the most that kept
// well within it, and afterwards every match anyone finished must be stored exactly once, as its
// players saw it, with a replay, and nothing left in progress.
#pragma once

#include <nlohmann/json.hpp>

namespace olympics::bench {

struct SoakOptions {
  double minutes = 60;         // the soak, after the ramp
  int matches = 0;             // client matches at once; 0: ramp up to the most within budget
  int ramp_step = 2;           // matches added per ramp step
  double ramp_window_s = 30;   // wall seconds per ramp step
  int workers = 0;             // server worker threads; 0: one per core
  double match_seconds = 20;   // simulated seconds per match
  double p99_budget_ms = 100;  // tick cycle
  // The ramp goes on until a step misses the budget, and the soak holds the most matches whose
  // step stayed under this share of it: a 30 s step is a noisy sample of an hour.
  double ramp_headroom = 0.6;
  bool league = true;           // an olympics-league process playing tournaments alongside
  bool signed_messages = true;  // a deployment secret, as a lab network would run
  bool keep = false;            // keep the folder (results, replays, logs) even when all is well
};

// Throws std::runtime_error when the server does not start.
nlohmann::json run_soak_bench(const SoakOptions& options);
void print_soak_report(const nlohmann::json& report);

}  // namespace olympics::bench
