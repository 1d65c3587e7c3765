// olympics-bench: performance figures, printed side by side with their references.
//
//   olympics-bench physics [--json] [--seconds S] [--repeats R] [--threads T] [--no-mujoco]
//   olympics-bench server  [--json] [--seconds S] [--matches M] [--workers W] [--vector]
//                          [--async K]
//   olympics-bench racket  [--json] [--episodes N] [--seconds S] [--repeats R]
//   olympics-bench combat  [--json] [--bouts N | --seeds A-B,..] [--seconds S] [--repeats R]
//   olympics-bench soccer  [--json] [--kicks N | --seeds A-B,..] [--matches M] [--half-s S]
//                          [--policies P,..]
//   olympics-bench basketball [--json] [--throws N | --seeds A-B,..] [--policies P,..]
//                             [--distances D,..]
//   olympics-bench soak    [--json] [--minutes M] [--matches N] [--workers W] (an hour; not CI)
//   olympics-bench vector  [--json] [--envs N] [--workers W] [--seconds S] [--async K]
//                          [--connect URL]
#include <CLI/CLI.hpp>
#include <cstdio>

#include "basketball_bench.h"
#include "bench_support.h"
#include "combat_bench.h"
#include "physics_bench.h"
#include "racket_bench.h"
#include "server_bench.h"
#include "soak_bench.h"
#include "soccer_bench.h"
#include "vector_bench.h"

int main(int argc, char** argv) {
  CLI::App app{"Performance figures for the humanoid sports server"};
  app.require_subcommand(1);
  bool json = false;
  olympics::bench::PhysicsBenchOptions physics;
  auto* phys = app.add_subcommand("physics", "physics steps/s vs MuJoCo on the same MJCF");
  phys->add_flag("--json", json, "print one JSON object instead of a table");
  phys->add_option("--seconds", physics.seconds, "wall seconds per measurement")
      ->check(CLI::PositiveNumber);
  phys->add_option("--repeats", physics.repeats, "interleaved repeats (median reported)")
      ->check(CLI::PositiveNumber);
  phys->add_option("--threads", physics.max_threads, "thread sweep up to this many (0: all cores)");
  bool no_mujoco = false;
  phys->add_flag("--no-mujoco", no_mujoco, "skip the MuJoCo side");
  olympics::bench::ServerBenchOptions server;
  auto* serv =
      app.add_subcommand("server", "match ticks/s over LCM vs bare physics, round-trip latency");
  serv->add_flag("--json", json, "print one JSON object instead of a table");
  serv->add_option("--seconds", server.seconds, "wall seconds to measure")
      ->check(CLI::PositiveNumber);
  serv->add_option("--matches", server.matches, "concurrent matches")->check(CLI::PositiveNumber);
  serv->add_option("--workers", server.workers, "server worker threads")
      ->check(CLI::PositiveNumber);
  bool no_pin = false;
  serv->add_flag("--no-pin", no_pin, "let the OS place the server's workers");
  serv->add_option("--lcm-provider", server.provider,
                   "udpm (one port for all) or mpudpm (channels hashed over 64 ports)")
      ->check(CLI::IsMember({"udpm", "mpudpm"}));
  serv->add_flag("--signed", server.signed_messages,
                 "with a deployment secret: every message signed and checked");
  serv->add_flag("--vector", server.vector_client,
                 "one vector client plays every match (bundled traffic), not one client each");
  serv->add_option("--async", server.async_batch,
                   "with --vector: async (EnvPool's send/recv), each recv taking this many ready "
                   "matches")
      ->check(CLI::PositiveNumber);
  serv->add_option("--live-viewers", server.live_viewers,
                   "this many HTTP clients watch the matches live (the viewer's cost)")
      ->check(CLI::NonNegativeNumber);
  olympics::bench::RacketBenchOptions racket;
  auto* rack = app.add_subcommand(
      "racket", "tennis / table tennis: scripted touch rate, match ticks/s vs bare physics");
  rack->add_flag("--json", json, "print one JSON object instead of a table");
  rack->add_option("--episodes", racket.episodes, "ball-return episodes per sport and policy")
      ->check(CLI::PositiveNumber);
  rack->add_option("--seconds", racket.seconds, "wall seconds per speed measurement")
      ->check(CLI::PositiveNumber);
  rack->add_option("--policies", racket.policies,
                   "ball-return players: scripted, zero, random, mlp:FILE (comma-separated)")
      ->delimiter(',');
  rack->add_option("--sports", racket.sports, "tennis, table_tennis (comma-separated)")
      ->delimiter(',');
  rack->add_flag("--no-speed{false}", racket.speed, "skip the 1v1 ticks/s measurement");
  rack->add_option("--repeats", racket.repeats, "interleaved repeats (median reported)")
      ->check(CLI::PositiveNumber);
  // A --seeds value: refused at parsing, saying what was wrong.
  const auto seed_list = [](const std::string& text) {
    try {
      olympics::bench::episode_seeds(text, 0);
      return std::string();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
  };
  olympics::bench::SoccerBenchOptions soccer;
  auto* socc = app.add_subcommand(
      "soccer", "soccer: penalty kicks scored by policy, scripted goals per 10 min, 2v2 ticks/s");
  socc->add_flag("--json", json, "print one JSON object instead of a table");
  socc->add_option("--kicks", soccer.kicks, "penalty kicks per policy (seeds 1..N)")
      ->check(CLI::PositiveNumber);
  socc->add_option("--seeds", soccer.seeds,
                   "penalty kick seeds instead, e.g. 5001-5500,7001-7200 (docs/figures.md)")
      ->check(seed_list);
  socc->add_option("--matches", soccer.matches, "scripted 1v1 and 2v2 matches (seeds 1..M)")
      ->check(CLI::NonNegativeNumber);
  socc->add_option("--half-s", soccer.half_s, "seconds per half of those matches")
      ->check(CLI::PositiveNumber);
  socc->add_option("--policies", soccer.policies, "penalty kickers (comma-separated)")
      ->delimiter(',');
  socc->add_flag("--no-speed{false}", soccer.speed, "skip the 2v2 ticks/s measurement");
  socc->add_option("--seconds", soccer.seconds, "wall seconds per speed measurement")
      ->check(CLI::PositiveNumber);
  socc->add_option("--repeats", soccer.repeats, "interleaved repeats (median reported)")
      ->check(CLI::PositiveNumber);
  olympics::bench::BasketballBenchOptions basketball;
  auto* bask = app.add_subcommand(
      "basketball", "basketball: free throws made by policy, 1v1 and 2v2 ticks/s vs bare physics");
  bask->add_flag("--json", json, "print one JSON object instead of a table");
  bask->add_option("--throws", basketball.throws, "free throws per policy (seeds 1..N)")
      ->check(CLI::PositiveNumber);
  bask->add_option("--seeds", basketball.seeds,
                   "free-throw seeds instead, e.g. 5001-5500,7001-7200 (docs/figures.md)")
      ->check(seed_list);
  bask->add_option("--policies", basketball.policies,
                   "free-throw shooters: scripted, zero, random, mlp:FILE (comma-separated)")
      ->delimiter(',');
  bask->add_option("--distances", basketball.scripted_distances,
                   "free-throw lines (m from the board) the scripted shooter also shoots from")
      ->delimiter(',');
  bool no_distances = false;
  bask->add_flag("--no-distances", no_distances, "the scripted shooter from the rule's line only");
  bask->add_flag("--no-speed{false}", basketball.speed, "skip the ticks/s measurements");
  bask->add_option("--seconds", basketball.seconds, "wall seconds per speed measurement")
      ->check(CLI::PositiveNumber);
  bask->add_option("--repeats", basketball.repeats, "interleaved repeats (median reported)")
      ->check(CLI::PositiveNumber);
  olympics::bench::CombatBenchOptions combat;
  auto* comb = app.add_subcommand(
      "combat", "fencing / boxing: touches and punches per minute by pairing, ticks/s vs bare");
  comb->add_flag("--json", json, "print one JSON object instead of a table");
  comb->add_option("--bouts", combat.bouts, "bouts per sport and pairing (seeds 1..N)")
      ->check(CLI::PositiveNumber);
  comb->add_option("--seeds", combat.seeds, "bout seeds instead, e.g. 5001-5500 (docs/figures.md)")
      ->check(seed_list);
  comb->add_option("--challenger", combat.challenger,
                   "measure this policy (mlp:FILE) in slot 0 against scripted");
  comb->add_option("--sports", combat.sports, "fencing, boxing (comma-separated)")->delimiter(',');
  comb->add_flag("--no-speed{false}", combat.speed, "skip the 1v1 ticks/s measurement");
  comb->add_option("--seconds", combat.seconds, "wall seconds per speed measurement")
      ->check(CLI::PositiveNumber);
  comb->add_option("--repeats", combat.repeats, "interleaved repeats (median reported)")
      ->check(CLI::PositiveNumber);
  olympics::bench::SoakOptions soak;
  auto* soa = app.add_subcommand(
      "soak",
      "one server, as many matches as hold a p99 tick cycle under budget, for an hour; "
      "then every result audited (exit 1 if not clean or over budget)");
  soa->add_flag("--json", json, "print one JSON object instead of a table");
  soa->add_option("--minutes", soak.minutes, "soak length after the ramp")
      ->check(CLI::PositiveNumber);
  soa->add_option("--matches", soak.matches, "client matches at once (default: ramp to the most)")
      ->check(CLI::NonNegativeNumber);
  soa->add_option("--ramp-step", soak.ramp_step, "matches added per ramp step")
      ->check(CLI::PositiveNumber);
  soa->add_option("--ramp-window", soak.ramp_window_s, "wall seconds per ramp step")
      ->check(CLI::PositiveNumber);
  soa->add_option("--workers", soak.workers, "server worker threads (default: one per core)")
      ->check(CLI::NonNegativeNumber);
  soa->add_option("--match-seconds", soak.match_seconds, "simulated seconds per match")
      ->check(CLI::PositiveNumber);
  soa->add_option("--p99-budget-ms", soak.p99_budget_ms, "tick cycle budget")
      ->check(CLI::PositiveNumber);
  soa->add_option("--ramp-headroom", soak.ramp_headroom,
                  "hold the most matches whose ramp step kept p99 under this share of the budget")
      ->check(CLI::Range(0.05, 1.0));
  bool no_league = false, unsigned_messages = false;
  soa->add_flag("--no-league", no_league, "clients only");
  soa->add_flag("--unsigned", unsigned_messages, "no deployment secret");
  soa->add_flag("--keep", soak.keep, "keep the folder of results, replays and logs");
  olympics::bench::VectorBenchOptions vector;
  auto* vect = app.add_subcommand(
      "vector", "one vector client's agent-steps/s over LCM vs bare physics on every core");
  vect->add_flag("--json", json, "print one JSON object instead of a table");
  vect->add_option("--envs", vector.envs, "matches the client plays at once")
      ->check(CLI::PositiveNumber);
  vect->add_option("--workers", vector.workers, "server worker threads (default: one per core)")
      ->check(CLI::NonNegativeNumber);
  vect->add_option("--seconds", vector.seconds, "wall seconds per measurement")
      ->check(CLI::PositiveNumber);
  vect->add_option("--async", vector.async_batch,
                   "async (EnvPool's send/recv): each recv takes this many ready matches")
      ->check(CLI::PositiveNumber);
  vect->add_option("--connect", vector.connect,
                   "LCM URL of a running olympics-server to play on (default: one in process)");
  CLI11_PARSE(app, argc, argv);

  if (*phys) {
    physics.with_mujoco = !no_mujoco;
    auto report = olympics::bench::run_physics_bench(physics);
    if (json)
      std::printf("%s\n", report.dump(2).c_str());
    else
      olympics::bench::print_physics_report(report);
  }
  if (*serv) {
    server.pin = !no_pin;
    auto report = olympics::bench::run_server_bench(server);
    if (json)
      std::printf("%s\n", report.dump(2).c_str());
    else
      olympics::bench::print_server_report(report);
  }
  if (*rack) {
    auto report = olympics::bench::run_racket_bench(racket);
    if (json)
      std::printf("%s\n", report.dump(2).c_str());
    else
      olympics::bench::print_racket_report(report);
  }
  if (*comb) {
    auto report = olympics::bench::run_combat_bench(combat);
    if (json)
      std::printf("%s\n", report.dump(2).c_str());
    else
      olympics::bench::print_combat_report(report);
  }
  if (*socc) {
    auto report = olympics::bench::run_soccer_bench(soccer);
    if (json)
      std::printf("%s\n", report.dump(2).c_str());
    else
      olympics::bench::print_soccer_report(report);
  }
  if (*bask) {
    if (no_distances) basketball.scripted_distances.clear();
    auto report = olympics::bench::run_basketball_bench(basketball);
    if (json)
      std::printf("%s\n", report.dump(2).c_str());
    else
      olympics::bench::print_basketball_report(report);
  }
  if (*vect) {
    auto report = olympics::bench::run_vector_bench(vector);
    if (json)
      std::printf("%s\n", report.dump(2).c_str());
    else
      olympics::bench::print_vector_report(report);
  }
  if (*soa) {
    soak.league = !no_league, soak.signed_messages = !unsigned_messages;
    auto report = olympics::bench::run_soak_bench(soak);
    if (json)
      std::printf("%s\n", report.dump(2).c_str());
    else
      olympics::bench::print_soak_report(report);
    if (!report["results_clean"].get<bool>() || !report["within_budget"].get<bool>()) return 1;
  }
  return 0;
}
