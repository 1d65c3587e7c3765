#include "fleet_bench.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#include "fixture_queue.h"
#include "latency_histogram.h"
#include "league_store.h"

namespace olympics::bench {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// A tournament of `fixtures` games between two bots, queued (the games are never played).
std::string queue_fixtures(const std::string& db, int fixtures) {
  selfplay::LeagueStore store(db);
  selfplay::TournamentSpec spec;
  spec.name =
      "bench-" + std::to_string(std::chrono::system_clock::now().time_since_epoch().count());
  spec.format = "round-robin";
  spec.options = "{}";
  spec.entrants = {{"zero", "zero", 1}, {"zero-2", "zero", 1}};
  store.create_tournament(spec);
  std::vector<selfplay::Game> games(fixtures);
  for (int i = 0; i < fixtures; ++i) games[i].index = i, games[i].away = 1;
  store.add_games(spec.name, games);
  selfplay::FixtureQueue(db, "bench").queue_pending(spec.name, "");
  return spec.name;
}

}  // namespace

nlohmann::json run_fleet_bench(const FleetBenchOptions& o) {
  std::string db = o.db;
  if (db.empty())
    if (const char* url = std::getenv("OLYMPICS_TEST_POSTGRES_URL")) db = url;
  if (db.empty())
    throw std::invalid_argument("give --db postgresql://... (or OLYMPICS_TEST_POSTGRES_URL)");
  const std::string name = queue_fixtures(db, o.fixtures);
  std::vector<LatencyHistogram> leases(o.cells), stores(o.cells);
  std::vector<int> stored(o.cells, 0);
  const auto start = Clock::now();
  {
    std::vector<std::jthread> cells;
    for (int c = 0; c < o.cells; ++c)
      cells.emplace_back([&, c] {
        selfplay::FixtureQueue queue(db, "bench-cell-" + std::to_string(c));
        for (;;) {
          const auto asked = Clock::now();
          const auto leased = queue.lease(name, "", o.batch, 30);
          leases[c].add(ms_since(asked));
          if (leased.empty()) return;
          for (int index : leased) {
            const auto storing = Clock::now();
            stored[c] += queue.store_result(name, {index, "m", 1.0, "bench", 1});
            stores[c].add(ms_since(storing));
          }
        }
      });
  }
  const double seconds = ms_since(start) / 1000;
  for (int c = 1; c < o.cells; ++c) leases[0].merge(leases[c]), stores[0].merge(stores[c]);
  int total = 0;
  for (int s : stored) total += s;
  return {{"fixtures", o.fixtures},
          {"cells", o.cells},
          {"batch", o.batch},
          {"stored", total},
          {"seconds", seconds},
          {"fixtures_per_s", total / seconds},
          {"lease_ms_p50", leases[0].percentile_ms(0.5)},
          {"lease_ms_p99", leases[0].percentile_ms(0.99)},
          {"lease_ms_max", leases[0].max_ms()},
          {"store_ms_p50", stores[0].percentile_ms(0.5)},
          {"store_ms_p99", stores[0].percentile_ms(0.99)}};
}

void print_fleet_report(const nlohmann::json& r) {
  std::printf(
      "fleet queue: %d fixtures, %d cells, batch %d: %d stored in %.2f s = %.0f fixtures/s\n",
      r["fixtures"].get<int>(), r["cells"].get<int>(), r["batch"].get<int>(),
      r["stored"].get<int>(), r["seconds"].get<double>(), r["fixtures_per_s"].get<double>());
  std::printf(
      "lease p50 %.1f ms, p99 %.1f ms, max %.1f ms; result stored p50 %.1f ms, p99 %.1f ms\n",
      r["lease_ms_p50"].get<double>(), r["lease_ms_p99"].get<double>(),
      r["lease_ms_max"].get<double>(), r["store_ms_p50"].get<double>(),
      r["store_ms_p99"].get<double>());
}

}  // namespace olympics::bench
