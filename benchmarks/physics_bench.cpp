#include "physics_bench.h"

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <random>
#include <thread>

#include "bench_support.h"
#include "core/humanoid_assets.h"
#include "core/humanoid_scene.h"
#include "mujoco_scene.h"

namespace olympics::bench {
namespace {

using core::HumanoidScene;
using Clock = std::chrono::steady_clock;
constexpr double kSpacing = 1.0;

// A fixed pool of random actions in [-1, 1], cycled, so both engines see the same sequence and
// no random numbers are drawn inside the timed loop.
struct ActionPool {
  explicit ActionPool(int dof, unsigned seed = 1) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1, 1);
    actions.resize(64, std::vector<float>(dof));
    for (auto& a : actions)
      for (auto& x : a) x = u(rng);
  }
  const std::vector<float>& next() { return actions[i++ % actions.size()]; }
  std::vector<std::vector<float>> actions;
  size_t i = 0;
};

std::unique_ptr<HumanoidScene> make_scene(const core::ModelSpec& spec, int humanoids) {
  auto scene = std::make_unique<HumanoidScene>();
  for (int h = 0; h < humanoids; ++h)
    scene->add_humanoid(spec, {{h * kSpacing, 0, 0}, h % 2 ? M_PI : 0.0});
  return scene;
}

// Physics steps per wall second for `seconds`, ticking at the control rate with fresh actions.
template <typename TickFn>
double steps_per_second(double seconds, int substeps, TickFn tick) {
  long steps = 0;
  auto start = Clock::now();
  double elapsed = 0;
  while (elapsed < seconds) {
    for (int k = 0; k < 30; ++k) tick();  // one simulated second per clock check
    steps += 30L * substeps;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  }
  return steps / elapsed;
}

double ours(const core::ModelSpec& spec, int humanoids, double seconds) {
  auto scene = make_scene(spec, humanoids);
  ActionPool pool(spec.dof_count());
  return steps_per_second(seconds, scene->settings().substeps, [&] {
    for (int h = 0; h < humanoids; ++h) scene->set_action(h, pool.next());
    scene->tick();
  });
}

struct MujocoConfig {
  const char* key;         // JSON key
  const char* integrator;  // MuJoCo option
  bool match_solver;       // PGS with our iteration count, instead of MuJoCo's Newton default
};
// Implicit is the fair configuration: MuJoCo's position actuators are explicit springs and its
// Euler integrator diverges within a second at this step under random actions, while the
// implicit integrator stays stable, like our implicit PD. Euler is timed too, as the cheapest
// MuJoCo step, and its divergence is reported.
constexpr MujocoConfig kMujocoConfigs[] = {
    {"mujoco_implicit", "implicit", false},
    {"mujoco_implicit_pgs", "implicit", true},
    {"mujoco_euler", "Euler", false},
};

// Steps/s of MuJoCo on the same scene; sets `diverged` when MuJoCo had to reset the state.
double mujoco(const core::ModelSpec& spec, int humanoids, double seconds, const MujocoConfig& c,
              bool& diverged) {
  HumanoidScene probe;  // our scene settings and standing height, so both start alike
  int i = probe.add_humanoid(spec);
  MujocoSceneOptions o;
  o.asset_path = core::humanoid_asset_path(core::HumanoidKind::Smpl);
  o.humanoids = humanoids;
  o.timestep = probe.settings().physics_dt();
  o.spacing = kSpacing;
  o.root_height = probe.humanoid(i).standing_root_height();
  o.match_solver = c.match_solver;
  o.integrator = c.integrator;
  o.solver_iterations = probe.settings().world.solver_iterations;
  MujocoScene scene(o);
  ActionPool pool(spec.dof_count());
  std::vector<double> targets(spec.dof_count());
  const int substeps = probe.settings().substeps;
  double rate = steps_per_second(seconds, substeps, [&] {
    for (int h = 0; h < humanoids; ++h) {
      probe.action_map(i).targets(pool.next(), targets);
      scene.set_targets(h, targets);
    }
    for (int s = 0; s < substeps; ++s) scene.step();
  });
  diverged = diverged || !scene.finite();
  return rate;
}

// Heap bytes in use (glibc), to count what a world allocates.
long heap_bytes() {
  struct mallinfo2 info = mallinfo2();
  return static_cast<long>(info.uordblks + info.hblkhd);
}

// Heap memory per 1v1 world, from creating many and dividing. ODE's per-step solver arena is
// per world and included (each world is ticked once before counting).
double bytes_per_world(const core::ModelSpec& spec) {
  constexpr int kWorlds = 32;
  std::vector<std::unique_ptr<HumanoidScene>> worlds;
  long before = heap_bytes();
  for (int w = 0; w < kWorlds; ++w) {
    worlds.push_back(make_scene(spec, 2));
    worlds.back()->tick();
  }
  return static_cast<double>(heap_bytes() - before) / kWorlds;
}

// Aggregate physics steps/s of `threads` 1v1 worlds, one per thread.
double threaded(const core::ModelSpec& spec, int threads, double seconds) {
  return sum_over_threads(threads, [&](int) { return ours(spec, 2, seconds); });
}

}  // namespace

nlohmann::json run_physics_bench(const PhysicsBenchOptions& o) {
  mju_user_warning = [](const char*) {};  // divergence is detected and reported instead
  const core::ModelSpec spec = core::load_humanoid(core::HumanoidKind::Smpl);
  HumanoidScene probe;
  const double dt = probe.settings().physics_dt();
  nlohmann::json report;
  report["physics_dt"] = dt;
  report["substeps_per_tick"] = probe.settings().substeps;
  report["solver_iterations"] = probe.settings().world.solver_iterations;
  report["humanoid"] = "smpl (24 bodies, 69 DoF)";
  report["mujoco_version"] = mj_versionString();
  report["bytes_per_1v1_world"] = bytes_per_world(spec);
  report["cores"] = std::thread::hardware_concurrency();

  for (int n : {1, 2, 4}) {
    std::vector<double> ours_r;
    std::map<std::string, std::vector<double>> mj_r;
    std::map<std::string, bool> mj_diverged;
    for (int r = 0; r < o.repeats; ++r) {  // interleaved, so machine noise hits both engines
      ours_r.push_back(ours(spec, n, o.seconds));
      if (o.with_mujoco)
        for (const auto& c : kMujocoConfigs)
          mj_r[c.key].push_back(mujoco(spec, n, o.seconds, c, mj_diverged[c.key]));
    }
    nlohmann::json row;
    row["humanoids"] = n;
    row["steps_per_s"] = median(ours_r);
    row["realtime_factor"] = median(ours_r) * dt;
    for (const auto& [key, rates] : mj_r)
      row[key] = {{"steps_per_s", median(rates)},
                  {"ratio_ours_over_mujoco", median(ours_r) / median(rates)},
                  {"diverged", mj_diverged[key]}};
    report["scenes"].push_back(row);
  }

  int max_threads =
      o.max_threads > 0 ? o.max_threads : static_cast<int>(std::thread::hardware_concurrency());
  for (int t = 1; t <= max_threads; t *= 2) {
    double total = threaded(spec, t, o.seconds);
    report["threads"].push_back(
        {{"threads", t}, {"total_steps_per_s", total}, {"total_realtime_factor", total * dt}});
    if (t < max_threads && t * 2 > max_threads) t = max_threads / 2;  // end on max_threads
  }
  return report;
}

void print_physics_report(const nlohmann::json& r) {
  std::printf("physics: SMPL humanoids, dt %.5f s (%d substeps per 30 Hz tick), QuickStep %d\n",
              r["physics_dt"].get<double>(), r["substeps_per_tick"].get<int>(),
              r["solver_iterations"].get<int>());
  std::printf("%-10s %10s %11s", "humanoids", "steps/s", "x realtime");
  for (const auto& c : kMujocoConfigs) std::printf(" | %-19s %6s", c.key, "ratio");
  std::printf("\n");
  for (const auto& row : r["scenes"]) {
    std::printf("%-10d %10.0f %11.1f", row["humanoids"].get<int>(),
                row["steps_per_s"].get<double>(), row["realtime_factor"].get<double>());
    for (const auto& c : kMujocoConfigs) {
      if (!row.contains(c.key)) continue;
      const auto& m = row[c.key];
      std::printf(" | %10.0f%-9s %6.2f", m["steps_per_s"].get<double>(),
                  m["diverged"].get<bool>() ? " DIVERGED" : "",
                  m["ratio_ours_over_mujoco"].get<double>());
    }
    std::printf("\n");
  }
  std::printf("ratio = our steps/s over MuJoCo's, same scene, same step, same actions\n");
  std::printf("memory per 1v1 world: %.0f KiB\n", r["bytes_per_1v1_world"].get<double>() / 1024);
  for (const auto& t : r["threads"])
    std::printf("%2d threads x 1v1 world: %.0f steps/s total, %.1f x realtime total\n",
                t["threads"].get<int>(), t["total_steps_per_s"].get<double>(),
                t["total_realtime_factor"].get<double>());
}

}  // namespace olympics::bench
