// The cross-entropy search the scripted athletes' poses and times were found by (run by hand
// from disabled tests: the javelin thrower, the long and high jumpers): each iteration draws
// `candidates` parameter vectors from independent normals, scores each, and refits the normals'
// means and spreads to the best `elite`. It prints each iteration's best and mean, so a run can
// be stopped and its numbers copied into the baseline.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <utility>
#include <vector>

namespace olympics::sports::athletics {

struct CrossEntropyRun {
  int iterations = 12, candidates = 150, elite = 15;
  double min_sd = 0.03;  // the spreads never shrink below this
  std::uint64_t rng_seed = 1;
};

// A run sized by hand from the environment, as the disabled search tests take it: ITER
// iterations (else `iterations`) of CANDIDATES candidates (else 150), the best tenth kept.
inline CrossEntropyRun cross_entropy_run_from_env(int iterations) {
  CrossEntropyRun run;
  run.iterations = std::getenv("ITER") ? std::atoi(std::getenv("ITER")) : iterations;
  run.candidates = std::getenv("CANDIDATES") ? std::atoi(std::getenv("CANDIDATES")) : 150;
  run.elite = run.candidates / 10;
  return run;
}

// Returns the means after the last iteration; `mean` and `sd` are the starting normals.
inline std::vector<double> cross_entropy_search(
    std::vector<double> mean, std::vector<double> sd,
    const std::function<double(const std::vector<double>&)>& score, const CrossEntropyRun& run) {
  std::mt19937_64 rng(run.rng_seed);
  const size_t dims = mean.size();
  for (int it = 0; it < run.iterations; ++it) {
    std::vector<std::pair<double, std::vector<double>>> population;
    for (int k = 0; k < run.candidates; ++k) {
      std::vector<double> x(dims);
      for (size_t d = 0; d < dims; ++d)
        x[d] = std::normal_distribution<double>(mean[d], sd[d])(rng);
      population.push_back({score(x), x});
    }
    std::sort(population.begin(), population.end(),
              [](const auto& a, const auto& b) { return a.first > b.first; });
    for (size_t d = 0; d < dims; ++d) {
      double m = 0, v = 0;
      for (int e = 0; e < run.elite; ++e) m += population[e].second[d];
      m /= run.elite;
      for (int e = 0; e < run.elite; ++e) v += std::pow(population[e].second[d] - m, 2);
      mean[d] = m, sd[d] = std::max(std::sqrt(v / run.elite), run.min_sd);
    }
    std::printf("iter %d best %.3f elite's worst %.3f\n  best:", it, population[0].first,
                population[run.elite - 1].first);
    for (double v : population[0].second) std::printf(" %.3f", v);
    std::printf("\n  mean:");
    for (double v : mean) std::printf(" %.3f", v);
    std::printf("\n");
    std::fflush(stdout);
  }
  return mean;
}

}  // namespace olympics::sports::athletics
