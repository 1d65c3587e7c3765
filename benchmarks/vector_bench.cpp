#include "vector_bench.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <memory>
#include <thread>

#include "bench_support.h"
#include "match_host.h"
#include "results_store.h"
#include "vector_client.h"
#include "zero_vector_play.h"

namespace olympics::bench {
namespace {
using Clock = std::chrono::steady_clock;
constexpr int kAgents = 2;  // sandbox 1v1, both slots played by the vector client

// Bare physics of the same scene on every core at once: one thread per core, each stepping
// as many sandbox matches as the server's workers hold per core, back to back; total ticks per
// second. (As many: 128 worlds a core step about 12% slower than 4, which fit the caches.)
double bare_ticks_all_cores(int cores, int matches_per_core, double seconds) {
  return sum_over_threads(
      cores, [&](int) { return sandbox_tick_rate(matches_per_core, seconds).per_second; });
}

// Agent-steps per second of one vector client playing zero actions, for `seconds`.
double vector_agent_steps(ZeroVectorPlay& play, double seconds) {
  long steps = 0;
  const auto start = Clock::now();
  double elapsed = 0;
  while (elapsed < seconds) {
    steps += play.round() * kAgents;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  }
  return steps / elapsed;
}

}  // namespace

nlohmann::json run_vector_bench(const VectorBenchOptions& o) {
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int workers = o.workers > 0 ? o.workers : cores;
  std::string url = o.connect;
  std::unique_ptr<server::ResultsStore> store;
  std::unique_ptr<protocol::Transport> transport;
  std::unique_ptr<server::MatchHost> host;
  std::atomic<bool> stop{false};
  std::thread server_thread;
  char db[] = "/tmp/olympics-vector-bench-XXXXXX";
  if (url.empty()) {
    url = "udpm://239.255.76.67:" + std::to_string(18000 + getpid() % 10000) +
          "?ttl=0&recv_buf_size=8388608";
    close(mkstemp(db));
    store = std::make_unique<server::ResultsStore>(db);
    transport = std::make_unique<protocol::Transport>(protocol::TransportOptions(url));
    server::HostSettings settings;
    settings.log_finished = false;  // stdout is the report's (--json)
    settings.server_id = "vector-bench";
    settings.workers = workers;
    settings.capacity = o.envs * 4;
    settings.sync.action_deadline_s = 30;  // the client pauses while the bare figure is taken
    host = std::make_unique<server::MatchHost>(settings, *transport, *store);
    server_thread = std::thread([&] { host->run(stop); });
  }
  client::ClientOptions co;
  co.lcm_url = url;
  co.agent_name = "vector-bench";
  client::VectorSettings vs;
  vs.num_envs = o.envs;
  vs.request.sport = "sandbox";
  vs.request.mode = "1v1";
  vs.request.time_limit_s = 20;
  client::VectorClient c(co, vs);
  ZeroVectorPlay play(c, o.async_batch);
  vector_agent_steps(play, 0.5);  // every match under way
  // Served and bare windows alternate so the machine's noise hits both alike.
  constexpr int kRounds = 5;
  std::vector<double> served, bare, ratios;
  for (int round = 0; round < kRounds; ++round) {
    served.push_back(vector_agent_steps(play, o.seconds / kRounds));
    bare.push_back(bare_ticks_all_cores(cores, std::max(1, o.envs / cores), o.seconds / kRounds) *
                   kAgents);
    ratios.push_back(served.back() / bare.back());
  }
  if (host) {
    stop = true;
    server_thread.join();
    std::remove(db);
  }
  return {{"scene", "sandbox 1v1 (2 SMPL humanoids), zero actions, sync mode"},
          {"envs", o.envs},
          {"mode", o.async_batch > 0 ? "async, recv of " + std::to_string(o.async_batch) : "sync"},
          {"agents_per_env", kAgents},
          {"server", o.connect.empty() ? "in process" : o.connect},
          {"server_workers", o.connect.empty() ? workers : 0},
          {"cores", cores},
          {"vector_agent_steps_per_s", median(served)},
          {"bare_agent_steps_per_s_all_cores", median(bare)},
          {"ratio_vector_over_bare", median(ratios)},
          {"ratios", ratios}};
}

void print_vector_report(const nlohmann::json& r) {
  std::printf(
      "vector client: %s, %d matches in one client (%s), server %s (%d workers), %d cores\n",
      r["scene"].get<std::string>().c_str(), r["envs"].get<int>(),
      r["mode"].get<std::string>().c_str(), r["server"].get<std::string>().c_str(),
      r["server_workers"].get<int>(), r["cores"].get<int>());
  std::printf("  vector client   %9.0f agent-steps/s\n",
              r["vector_agent_steps_per_s"].get<double>());
  std::printf("  bare physics    %9.0f agent-steps/s (same scene, every core, no network)\n",
              r["bare_agent_steps_per_s_all_cores"].get<double>());
  std::printf("  ratio           %9.2f (median of %s)\n", r["ratio_vector_over_bare"].get<double>(),
              r["ratios"].dump().c_str());
}

}  // namespace olympics::bench
