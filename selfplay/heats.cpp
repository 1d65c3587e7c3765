#include "heats.h"

#include <algorithm>
#include <numeric>
#include <random>
#include <regex>
#include <stdexcept>

namespace olympics::selfplay {
namespace {

constexpr int kDraws = 64;  // random partitions tried per round

// A Fisher-Yates shuffle from the raw bits (std::shuffle's draws differ between standard
// libraries, and a schedule must be the same on every platform).
void shuffle(std::vector<int>& v, std::mt19937_64& rng) {
  for (size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[rng() % i]);
}

}  // namespace

int ranked_seats(const std::string& mode) {
  static const std::regex pattern(R"(competition_(\d+))");
  std::smatch m;
  if (!std::regex_match(mode, m, pattern)) return 0;
  return std::stoi(m[1]);
}

void check_ranked_tournament(const std::string& mode, const std::string& format, int entrants) {
  const int seats = ranked_seats(mode);
  if (seats == 0) return;
  if (seats < 2)
    throw std::invalid_argument("--mode " + mode + " seats " + std::to_string(seats) +
                                " entrant: nothing to rank; choose competition_2 .. competition_8");
  if (seats > 2 && format != "round-robin" && format != "double-round-robin" && format != "swiss" &&
      format != "knockout")
    throw std::invalid_argument(
        "--mode " + mode + " ranks " + std::to_string(seats) +
        " entrants in each match: it plays --format round-robin (heats until every entrant has "
        "met every other), double-round-robin (twice), swiss (heats drawn by standing) or "
        "knockout (the top places of each heat go through); " +
        format + " pairs two entrants per game");
  if (entrants < seats)
    throw std::invalid_argument("--mode " + mode + " seats " + std::to_string(seats) +
                                " entrants in each match; there are " + std::to_string(entrants) +
                                ": add entrants, or choose competition_" +
                                std::to_string(std::max(entrants, 2)));
}

std::vector<Pairing> heats(int entrants, int seats, std::uint64_t seed, int meetings) {
  if (seats < 2 || entrants < seats)
    throw std::invalid_argument("heats of " + std::to_string(seats) + " need at least two seats " +
                                "and as many entrants; there are " + std::to_string(entrants));
  const int n = entrants;
  std::vector<std::vector<int>> met(n, std::vector<int>(n, 0));
  std::vector<int> appearances(n, 0);
  auto unmet_pairs = [&] {
    int count = 0;
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b) count += met[a][b] < meetings;
    return count;
  };
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ULL + 0x68656174ULL);  // "heat"
  std::vector<Pairing> out;
  for (int round = 0; unmet_pairs() > 0; ++round) {
    if (round > 64 * n)  // never seen: each round brings unmet pairs together with high odds
      throw std::logic_error("heats: no schedule covering every pair found");
    // Who rests: those with the most appearances, ties drawn.
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    shuffle(order, rng);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return appearances[a] > appearances[b]; });
    std::vector<int> playing(order.begin() + n % seats, order.end());
    std::vector<int> best;
    int best_gain = -1;
    for (int draw = 0; draw < kDraws; ++draw) {
      shuffle(playing, rng);
      int gain = 0;
      for (size_t h = 0; h < playing.size(); h += seats)
        for (int i = 0; i < seats; ++i)
          for (int j = i + 1; j < seats; ++j)
            gain += met[playing[h + i]][playing[h + j]] < meetings;
      if (gain > best_gain) best_gain = gain, best = playing;
    }
    for (size_t h = 0; h < best.size(); h += seats) {
      std::vector<int> heat(best.begin() + static_cast<long>(h),
                            best.begin() + static_cast<long>(h) + seats);
      for (int i = 0; i < seats; ++i) {
        ++appearances[heat[i]];
        for (int j = 0; j < seats; ++j)
          if (i != j) ++met[heat[i]][heat[j]];
      }
      out.push_back({round, heat[0], heat[1], heat});
    }
  }
  return out;
}

}  // namespace olympics::selfplay
