#include "server_bench.h"

#include <pthread.h>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <thread>

#include "auth.h"
#include "bench_support.h"
#include "match_client.h"
#include "match_host.h"
#include "registry.h"
#include "results_store.h"
#include "vector_client.h"
#include "view_server.h"
#include "zero_vector_play.h"

// Last: httplib.h (through OpenSSL and zlib) must come after Eigen, which it breaks otherwise.
#include <httplib.h>  // NOLINT

namespace olympics::bench {
namespace {

using Clock = std::chrono::steady_clock;

// Restricts the calling thread (and threads it starts later) to CPUs [first, last].
void pin_this_thread(int first, int last) {
  cpu_set_t set;
  CPU_ZERO(&set);
  for (int c = first; c <= last; ++c) CPU_SET(c, &set);
  pthread_setaffinity_np(pthread_self(), sizeof set, &set);
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(p * v.size()))];
}

// A person watching live: picks the `which`-th match being played from the server's list and
// follows its stream until it ends, then the next one; counts what arrives.
void watch_live(int port, int which, const std::atomic<bool>& stop, std::atomic<long>& bytes) {
  httplib::Client http("127.0.0.1", port);
  http.set_read_timeout(2, 0);
  while (!stop) {
    auto list = http.Get("/api/matches");
    std::string match;
    if (list && list->status == 200) {
      std::vector<std::string> playing;
      for (const auto& m : nlohmann::json::parse(list->body))
        if (!m.at("ended").get<bool>()) playing.push_back(m.at("match_id"));
      if (!playing.empty()) match = playing[which % playing.size()];
    }
    if (match.empty()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      continue;
    }
    http.Get("/api/live/" + match, [&](const char*, size_t n) {
      bytes += static_cast<long>(n);
      return !stop;
    });
  }
}

}  // namespace

nlohmann::json run_server_bench(const ServerBenchOptions& o) {
  // mpudpm spreads channels over 64 ports (a socket hears only the ports of its channels).
  const bool multi_port = o.provider == "mpudpm";
  const std::string url = o.provider +
                          "://239.255.76.67:" + std::to_string(17000 + getpid() % 1000 * 10) +
                          "?ttl=0&recv_buf_size=4194304" + (multi_port ? "&nports=64" : "");
  char db[] = "/tmp/olympics-bench-XXXXXX";
  int fd = mkstemp(db);
  close(fd);
  server::ResultsStore store(db);
  // With --pin, the server's workers get cores 0..workers-1 to themselves and everything else
  // (clients, LCM threads, the server's receive loop) shares the rest, so "per worker" means
  // per core, as for the bare figure.
  const int cores = static_cast<int>(std::thread::hardware_concurrency());
  const bool pin = o.pin && cores > o.workers;
  if (pin) pin_this_thread(o.workers, cores - 1);
  // With a secret, server and clients sign and check every message, as a secured deployment.
  const std::string secret = o.signed_messages ? std::string(db) + ".secret" : "";
  if (o.signed_messages) protocol::write_new_secret(secret);
  protocol::Transport server_transport{protocol::TransportOptions(
      url, 0.0, 1, o.signed_messages ? protocol::load_secret(secret) : nullptr)};
  server::HostSettings settings;
  settings.log_finished = false;  // stdout is the report's (--json)
  settings.server_id = "bench";
  settings.workers = o.workers;
  settings.capacity = o.matches * 4;
  settings.sync.action_deadline_s = 30;  // clients pause while the bare figure is taken
  server::LiveScenes live;
  std::unique_ptr<server::ViewServer> view;
  if (o.live_viewers > 0) {
    settings.live = &live;
    view = std::make_unique<server::ViewServer>(live, "127.0.0.1", 0);
    view->start();
  }
  if (pin) pin_this_thread(0, o.workers - 1);
  server::MatchHost host(settings, server_transport, store);
  if (pin) pin_this_thread(o.workers, cores - 1);
  std::atomic<bool> stop_server{false};
  std::thread server_thread([&] { host.run(stop_server); });

  std::atomic<bool> stop_clients{false}, paused{false};
  std::atomic<long> ticks{0};
  std::vector<std::vector<double>> round_trips(o.matches);
  std::vector<std::thread> clients;
  if (o.vector_client)
    clients.emplace_back([&] {
      client::ClientOptions co;
      co.lcm_url = url;
      co.agent_name = "bench";
      co.secret_file = secret;
      client::VectorSettings vs;
      vs.num_envs = o.matches;
      client::VectorClient c(co, vs);
      ZeroVectorPlay play(c, o.async_batch);
      while (!stop_clients) {
        while (paused) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        const auto sent = Clock::now();
        ticks += play.round();  // an ended match is replaced at once
        round_trips[0].push_back(
            std::chrono::duration<double, std::micro>(Clock::now() - sent).count());
        c.take_results();
      }
    });
  for (int m = 0; m < o.matches && !o.vector_client; ++m)
    clients.emplace_back([&, m] {
      client::ClientOptions co;
      co.lcm_url = url;
      co.agent_name = "bench" + std::to_string(m);
      co.secret_file = secret;
      client::MatchClient c(co);
      for (int game = 0; !stop_clients; ++game) {
        client::MatchRequest req;
        req.request_id = "bench-" + std::to_string(m) + "-" + std::to_string(game);
        req.seed = game;
        auto created = c.request_match(req);
        c.join(created.match_id, {0, 1});
        std::vector<std::vector<float>> zero(2, std::vector<float>(created.action_size, 0.0f));
        auto sent = Clock::now();
        bool acted = false;
        while (auto obs = c.next()) {
          if (acted)
            round_trips[m].push_back(
                std::chrono::duration<double, std::micro>(Clock::now() - sent).count());
          if (obs->all_done()) break;
          while (paused) std::this_thread::sleep_for(std::chrono::milliseconds(1));
          sent = Clock::now();
          c.act(obs->tick, zero);
          acted = true;
          ++ticks;
        }
        c.wait_result();
      }
    });
  std::atomic<long> viewed_bytes{0};
  std::vector<std::thread> viewers;
  for (int v = 0; v < o.live_viewers; ++v)
    viewers.emplace_back([&, v] { watch_live(view->port(), v, stop_clients, viewed_bytes); });
  const auto measuring_from = Clock::now();
  // Served and bare windows alternate, so the machine's noise hits both alike; the ratio of each
  // pair is taken and the median reported.
  constexpr int kRounds = 3;
  const double window = o.seconds / kRounds;
  std::vector<double> served_rates, bare_rates, bare_cpu_rates, ratios, capacity_ratios;
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // matches under way
  for (int round = 0; round < kRounds; ++round) {
    const long before = ticks;
    const double cpu_before = host.worker_cpu_seconds();
    auto start = Clock::now();
    std::this_thread::sleep_for(std::chrono::duration<double>(window));
    const long served_ticks = ticks - before;
    const double worker_cpu = host.worker_cpu_seconds() - cpu_before;
    served_rates.push_back(served_ticks /
                           std::chrono::duration<double>(Clock::now() - start).count() / o.workers);
    paused = true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // in-flight ticks drain
    if (pin) pin_this_thread(0, 0);  // the bare figure: on a worker's core
    const TickRate bare = sandbox_tick_rate(std::max(1, o.matches / o.workers), window);
    bare_rates.push_back(bare.per_second);
    bare_cpu_rates.push_back(bare.per_cpu_second);
    if (pin) pin_this_thread(o.workers, cores - 1);
    paused = false;
    ratios.push_back(served_rates.back() / bare_rates.back());
    // The server's own cost: ticks per CPU second of the workers over ticks per CPU second of the
    // bare stepping (both CPU time, so a loaded machine's stolen time counts on neither side).
    capacity_ratios.push_back(served_ticks / worker_cpu / bare.per_cpu_second);
  }
  const double measured_s = std::chrono::duration<double>(Clock::now() - measuring_from).count();
  stop_clients = true;
  for (auto& t : clients) t.join();
  for (auto& t : viewers) t.join();
  if (view) view->stop();
  stop_server = true;
  server_thread.join();
  std::remove(db);
  if (o.signed_messages) std::remove(secret.c_str());

  std::vector<double> all;
  for (auto& r : round_trips) all.insert(all.end(), r.begin(), r.end());
  std::string who = "one client per match", timed = "action -> next observation round trip";
  if (o.vector_client && o.async_batch == 0) {
    who = "one vector client (bundles)";
    timed = "actions of every match -> next observations round trip";
  } else if (o.vector_client) {
    who = "one vector client (bundles), async, recv of " + std::to_string(o.async_batch);
    timed = "recv of " + std::to_string(o.async_batch) + " ready matches";
  }
  return {{"scene", "sandbox 1v1 (2 SMPL humanoids), zero actions, sync mode"},
          {"lcm_provider", o.provider},
          {"clients", who},
          {"timed", timed},
          {"signed_messages", o.signed_messages},
          {"live_viewers", o.live_viewers},
          {"live_view_bytes_per_s", viewed_bytes / measured_s},
          {"matches", o.matches},
          {"server_workers", o.workers},
          {"workers_pinned", pin},
          {"served_ticks_per_s_per_worker", percentile(served_rates, 0.5)},
          {"bare_physics_ticks_per_s", percentile(bare_rates, 0.5)},
          {"bare_physics_ticks_per_cpu_s", percentile(bare_cpu_rates, 0.5)},
          {"ratio_server_over_bare", percentile(ratios, 0.5)},
          {"ratios", ratios},
          {"ratio_per_worker_cpu_second", percentile(capacity_ratios, 0.5)},
          {"round_trip_us_p50", percentile(all, 0.5)},
          {"round_trip_us_p99", percentile(all, 0.99)},
          {"round_trips_measured", all.size()}};
}

void print_server_report(const nlohmann::json& r) {
  std::printf("server: %s, %d matches at once (%s), %d server worker(s)%s%s\n",
              r["scene"].get<std::string>().c_str(), r["matches"].get<int>(),
              r["clients"].get<std::string>().c_str(), r["server_workers"].get<int>(),
              r["workers_pinned"].get<bool>() ? ", pinned to cores of their own" : "",
              r["signed_messages"].get<bool>() ? ", every message signed and checked" : "");
  if (r["live_viewers"].get<int>() > 0)
    std::printf("  %d live viewers over HTTP received %.0f kB/s of scene data\n",
                r["live_viewers"].get<int>(), r["live_view_bytes_per_s"].get<double>() / 1000);
  std::printf("  served           %8.0f ticks/s per worker\n",
              r["served_ticks_per_s_per_worker"].get<double>());
  std::printf("  bare physics     %8.0f ticks/s on one core (same scene, no network)\n",
              r["bare_physics_ticks_per_s"].get<double>());
  std::printf("  ratio            %8.2f (server per worker / bare; median of %s)\n",
              r["ratio_server_over_bare"].get<double>(), r["ratios"].dump().c_str());
  std::printf(
      "  ticks per worker CPU-second / bare: %.2f (the server's own cost, whoever is slow)\n",
      r["ratio_per_worker_cpu_second"].get<double>());
  std::printf("  %s: p50 %.0f us, p99 %.0f us (%ld samples)\n",
              r["timed"].get<std::string>().c_str(), r["round_trip_us_p50"].get<double>(),
              r["round_trip_us_p99"].get<double>(), r["round_trips_measured"].get<long>());
}

}  // namespace olympics::bench
