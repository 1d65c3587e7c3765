#include "tournament.h"

#include <algorithm>
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

}  // namespace olympics::selfplay
