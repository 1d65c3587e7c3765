// Tournament schedules and standings.
#pragma once

#include <string>
#include <vector>

namespace olympics::selfplay {

struct Pairing {
  int round;
  int home, away;  // entrant indices; home plays slot 0 (team 0)
};

// Every pair once (double = twice, home and away swapped), in rounds where nobody plays twice
// (the circle method; with an odd count one entrant rests each round).
std::vector<Pairing> round_robin(int entrants, bool double_round = false);

struct GameResult {
  int home, away;
  double home_score;  // 1 win, 0.5 draw, 0 loss
};

struct Standing {
  int entrant;
  int played = 0, wins = 0, draws = 0, losses = 0;
  double points = 0;  // win 1, draw 0.5
};

// Sorted by points, then wins, then entrant index.
std::vector<Standing> standings(int entrants, const std::vector<GameResult>& results);

}  // namespace olympics::selfplay
