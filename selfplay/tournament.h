// Tournament schedules and standings.
#pragma once

#include <string>
#include <vector>

namespace olympics::selfplay {

struct Pairing {
  int round;
  int home, away;  // entrant indices; home plays slot 0 (team 0); away < 0: a bye for home
  // A ranked fixture of N entrants (an athletics competition_N): seats[t] plays team t; home and
  // away are seats[0] and seats[1]. Empty: a two-team game of home and away.
  std::vector<int> seats = {};
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
  int played = 0, wins = 0, draws = 0, losses = 0, byes = 0;
  double points = 0;  // win 1, draw 0.5, bye 1
};

// Sorted by points, then wins, then entrant index. A result with away < 0 is a bye.
std::vector<Standing> standings(int entrants, const std::vector<GameResult>& results);

// Swiss: ceil(log2 n) rounds. The next round pairs entrants in standing order, each with the next
// one it has not met yet; with an odd count the lowest-ranked entrant without a bye gets one.
int swiss_round_count(int entrants);
std::vector<Pairing> swiss_round(int entrants, int round, const std::vector<GameResult>& so_far);

// Knockout: the survivors in seed order (best first). Round 0 gives the top seeds byes up to a
// power of two; then best meets worst. The winner of a drawn game is the better seed.
std::vector<Pairing> knockout_round(const std::vector<int>& survivors, int round);
int knockout_winner(const GameResult& game);

}  // namespace olympics::selfplay
