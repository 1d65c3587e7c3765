// Swiss and knockout for ranked fixtures of N > 2 entrants (an athletics competition_N): rounds
// of heats of exactly N, each drawn once the round before it is over, from that round's places.
//
// Knockout: the field (all entrants at first) in seed order (entrant index, best first). A round
// seats floor(F / N) heats of N, seeds dealt to them serpentine (1, 2, .. H, H, .. 2, 1, 1, ..)
// so the heats are even; the F mod N best seeds rest and go through (byes); from each heat the
// top `advancing` places go through (the better seed first on a tie): half the heat (rounded
// up), or more where fewer would leave under N for the next round. The round whose field is
// exactly N is the final, and the tournament ends with it.
//
// Swiss: as many rounds as the two-entrant swiss (ceil(log2 E)). The first round's heats are
// dealt serpentine in seed order; later ones are drawn by standing: entrants sorted by points
// (in a heat of N, one for each heat-mate placed behind, a half for each tied; N - 1 for a win
// of the heat), then entrant index, and cut into consecutive heats of N. The E mod N entrants
// that rest in a round are the lowest-standing of those who have rested least; a rest is worth
// (N - 1) / 2 points for the draw (a heat's average). Heat-mates may meet again.
//
// Rests are no games (no bye rows: the league's table counts only heats played). Pure functions
// of their arguments.
#pragma once

#include <vector>

#include "tournament.h"

namespace olympics::selfplay {

// A ranked fixture played: its round, seats (entrant per team) and places (per team, 1 = first;
// empty when the match gave none: all tied).
struct HeatResult {
  int round = 0;
  std::vector<int> seats;
  std::vector<int> places;
};

// Knockout: the heats of the next round after `results` (all rounds before it complete); empty
// when the final has been run.
std::vector<Pairing> knockout_heats_round(int entrants, int seats,
                                          const std::vector<HeatResult>& results);

// How many of a heat go through in a knockout round whose field is `field` entrants.
int knockout_advancing(int field, int seats);

// Swiss: the next round's heats after `results`; empty when all rounds are played.
std::vector<Pairing> swiss_heats_round(int entrants, int seats,
                                       const std::vector<HeatResult>& results);

// Each entrant's swiss points for the draw (heats and rests) after `results`.
std::vector<double> swiss_heat_points(int entrants, int seats,
                                      const std::vector<HeatResult>& results);

}  // namespace olympics::selfplay
