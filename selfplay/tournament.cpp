#include "tournament.h"

#include <algorithm>
#include <functional>
#include <set>
#include <stdexcept>

namespace olympics::selfplay {

std::vector<Pairing> round_robin(int entrants, bool double_round) {
  if (entrants < 2) throw std::invalid_argument("a round robin needs at least two entrants");
  // Circle method: fix the first seat, rotate the others; a dummy seat makes the count even.
  const int n = entrants % 2 ? entrants + 1 : entrants;
  std::vector<int> seats(n);
  for (int i = 0; i < n; ++i) seats[i] = i < entrants ? i : -1;
  std::vector<Pairing> out;
  for (int round = 0; round < n - 1; ++round) {
    for (int k = 0; k < n / 2; ++k) {
      int a = seats[k], b = seats[n - 1 - k];
      if (a < 0 || b < 0) continue;
      if (round % 2) std::swap(a, b);  // alternate who plays first
      out.push_back({round, a, b});
    }
    std::rotate(seats.begin() + 1, seats.end() - 1, seats.end());
  }
  if (double_round) {
    const size_t first_leg = out.size();
    for (size_t i = 0; i < first_leg; ++i)
      out.push_back({out[i].round + n - 1, out[i].away, out[i].home});
  }
  return out;
}

std::vector<Standing> standings(int entrants, const std::vector<GameResult>& results) {
  std::vector<Standing> table(entrants);
  for (int i = 0; i < entrants; ++i) table[i].entrant = i;
  for (const auto& r : results) {
    if (r.away < 0) {
      table.at(r.home).points += 1, ++table.at(r.home).byes;
      continue;
    }
    for (auto [who, score] :
         {std::pair{r.home, r.home_score}, std::pair{r.away, 1.0 - r.home_score}}) {
      Standing& s = table.at(who);
      ++s.played;
      s.points += score;
      if (score == 1.0)
        ++s.wins;
      else if (score == 0.5)
        ++s.draws;
      else
        ++s.losses;
    }
  }
  std::sort(table.begin(), table.end(), [](const Standing& a, const Standing& b) {
    if (a.points != b.points) return a.points > b.points;
    if (a.wins != b.wins) return a.wins > b.wins;
    return a.entrant < b.entrant;
  });
  return table;
}

int swiss_round_count(int entrants) {
  int rounds = 0;
  while ((1 << rounds) < entrants) ++rounds;
  return std::max(rounds, 1);
}

std::vector<Pairing> swiss_round(int entrants, int round, const std::vector<GameResult>& so_far) {
  std::set<std::pair<int, int>> met;
  std::set<int> had_bye;
  for (const auto& r : so_far) {
    if (r.away < 0)
      had_bye.insert(r.home);
    else
      met.insert({std::min(r.home, r.away), std::max(r.home, r.away)});
  }
  std::vector<int> order;
  for (const auto& s : standings(entrants, so_far)) order.push_back(s.entrant);
  std::vector<Pairing> out;
  if (order.size() % 2) {
    for (auto it = order.rbegin(); it != order.rend(); ++it)
      if (!had_bye.count(*it)) {
        out.push_back({round, *it, -1});
        order.erase(std::next(it).base());
        break;
      }
    if (out.empty()) {  // everyone had one: the last again
      out.push_back({round, order.back(), -1});
      order.pop_back();
    }
  }
  // Pair in standing order, each with the next entrant it has not met, backtracking when that
  // leaves the rest unpairable; only if no rematch-free pairing exists are rematches allowed.
  std::vector<std::pair<int, int>> pairs;
  auto unmet = [&](int a, int b) { return !met.count({std::min(a, b), std::max(a, b)}); };
  std::function<bool(std::vector<int>&, bool)> pair_up = [&](std::vector<int>& left, bool strict) {
    if (left.empty()) return true;
    const int a = left.front();
    for (size_t k = 1; k < left.size(); ++k) {
      const int b = left[k];
      if (strict && !unmet(a, b)) continue;
      std::vector<int> rest;
      for (size_t j = 1; j < left.size(); ++j)
        if (j != k) rest.push_back(left[j]);
      pairs.emplace_back(a, b);
      if (pair_up(rest, strict)) return true;
      pairs.pop_back();
    }
    return false;
  };
  if (!pair_up(order, true)) pair_up(order, false);
  for (auto [a, b] : pairs) out.push_back({round, a, b});
  return out;
}

std::vector<Pairing> knockout_round(const std::vector<int>& survivors, int round) {
  std::vector<Pairing> out;
  size_t bracket = 1;
  while (bracket < survivors.size()) bracket *= 2;
  const size_t byes = round == 0 ? bracket - survivors.size() : 0;
  for (size_t i = 0; i < byes; ++i) out.push_back({round, survivors[i], -1});
  std::vector<int> rest(survivors.begin() + static_cast<long>(byes), survivors.end());
  for (size_t i = 0; i < rest.size() / 2; ++i)
    out.push_back({round, rest[i], rest[rest.size() - 1 - i]});
  return out;
}

int knockout_winner(const GameResult& g) {
  if (g.away < 0) return g.home;
  if (g.home_score > 0.5) return g.home;
  if (g.home_score < 0.5) return g.away;
  return std::min(g.home, g.away);  // a draw: the better seed goes through
}

}  // namespace olympics::selfplay
