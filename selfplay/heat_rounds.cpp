#include "heat_rounds.h"

#include <algorithm>
#include <numeric>
#include <set>

namespace olympics::selfplay {
namespace {

// `field` (in order, best first) dealt serpentine into `heats` heats of `seats`.
std::vector<std::vector<int>> deal_serpentine(const std::vector<int>& field, int heats) {
  std::vector<std::vector<int>> out(heats);
  for (size_t i = 0; i < field.size(); ++i) {
    const int row = static_cast<int>(i) / heats, col = static_cast<int>(i) % heats;
    out[row % 2 == 0 ? col : heats - 1 - col].push_back(field[i]);
  }
  return out;
}

std::vector<Pairing> as_pairings(const std::vector<std::vector<int>>& heats, int round) {
  std::vector<Pairing> out;
  for (const auto& h : heats) out.push_back({round, h[0], h[1], h});
  return out;
}

// A heat's place for its team t (all tied when the match gave no places).
int place_of(const HeatResult& r, size_t t) {
  return r.places.size() == r.seats.size() ? r.places[t] : 1;
}

int rounds_played(const std::vector<HeatResult>& results) {
  int rounds = 0;
  for (const auto& r : results) rounds = std::max(rounds, r.round + 1);
  return rounds;
}

}  // namespace

int knockout_advancing(int field, int seats) {
  const int heats = field / seats, rest = field % seats;
  if (heats == 0) return 0;
  const int half = (seats + 1) / 2;
  const int enough = (seats - rest + heats - 1) / heats;  // so that rest + heats x it >= seats
  return std::min(seats - 1, std::max(half, enough));
}

std::vector<Pairing> knockout_heats_round(int entrants, int seats,
                                          const std::vector<HeatResult>& results) {
  std::vector<int> field(entrants);
  std::iota(field.begin(), field.end(), 0);
  const int rounds = rounds_played(results);
  for (int round = 0; round < rounds; ++round) {
    if (static_cast<int>(field.size()) <= seats) return {};  // that round was the final
    const int advancing = knockout_advancing(static_cast<int>(field.size()), seats);
    std::set<int> through(field.begin(), field.end());
    for (const auto& r : results) {
      if (r.round != round) continue;
      std::vector<size_t> order(r.seats.size());
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        if (place_of(r, a) != place_of(r, b)) return place_of(r, a) < place_of(r, b);
        return r.seats[a] < r.seats[b];  // a tie: the better seed
      });
      for (size_t k = static_cast<size_t>(advancing); k < order.size(); ++k)
        through.erase(r.seats[order[k]]);
    }
    field.clear();  // seed order
    for (int e : through) field.push_back(e);
  }
  if (rounds > 0 && static_cast<int>(field.size()) < seats) return {};
  const int heats = static_cast<int>(field.size()) / seats;
  const int resting = static_cast<int>(field.size()) % seats;  // the best seeds: byes
  std::vector<int> playing;
  for (size_t i = static_cast<size_t>(resting); i < field.size(); ++i) playing.push_back(field[i]);
  return as_pairings(deal_serpentine(playing, heats), rounds);
}

std::vector<double> swiss_heat_points(int entrants, int seats,
                                      const std::vector<HeatResult>& results) {
  std::vector<double> points(entrants, 0.0);
  const int rounds = rounds_played(results);
  std::vector<std::vector<char>> played(rounds, std::vector<char>(entrants, 0));
  for (const auto& r : results) {
    for (size_t a = 0; a < r.seats.size(); ++a) {
      played[r.round][r.seats[a]] = 1;
      for (size_t b = 0; b < r.seats.size(); ++b) {
        if (a == b) continue;
        if (place_of(r, a) < place_of(r, b)) points[r.seats[a]] += 1;
        if (place_of(r, a) == place_of(r, b)) points[r.seats[a]] += 0.5;
      }
    }
  }
  for (int round = 0; round < rounds; ++round)
    for (int e = 0; e < entrants; ++e)
      if (!played[round][e]) points[e] += 0.5 * (seats - 1);
  return points;
}

std::vector<Pairing> swiss_heats_round(int entrants, int seats,
                                       const std::vector<HeatResult>& results) {
  const int rounds = rounds_played(results);
  if (rounds >= swiss_round_count(entrants)) return {};
  const int heats = entrants / seats;
  std::vector<int> order(entrants);
  std::iota(order.begin(), order.end(), 0);
  if (rounds == 0) {  // seed order, dealt serpentine; the lowest seeds rest
    order.resize(static_cast<size_t>(heats * seats));
    return as_pairings(deal_serpentine(order, heats), 0);
  }
  const std::vector<double> points = swiss_heat_points(entrants, seats, results);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return points[a] > points[b]; });
  // Who rests: the lowest-standing of those with the fewest rests so far.
  std::vector<int> rests(entrants, rounds);
  for (const auto& r : results)
    for (int e : r.seats) --rests[e];  // one heat a round each: rests = rounds - heats played
  std::vector<int> by_rest = order;
  std::reverse(by_rest.begin(), by_rest.end());
  std::stable_sort(by_rest.begin(), by_rest.end(),
                   [&](int a, int b) { return rests[a] < rests[b]; });
  std::set<int> resting;
  for (int i = 0; i < entrants % seats; ++i) resting.insert(by_rest[static_cast<size_t>(i)]);
  std::vector<int> playing;
  for (int e : order)
    if (!resting.count(e)) playing.push_back(e);
  std::vector<std::vector<int>> cut(heats);
  for (size_t i = 0; i < playing.size(); ++i)
    cut[i / static_cast<size_t>(seats)].push_back(playing[i]);
  return as_pairings(cut, rounds);
}

}  // namespace olympics::selfplay
