// Schedules for ranked fixtures of N entrants (an athletics competition_N: N athletes, each its
// own team, ranked by places): heats of N drawn from a field of E >= N entrants.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tournament.h"

namespace olympics::selfplay {

// The number of entrants a mode seats in one ranked fixture: N for "competition_N" (the
// framework's N-athlete modes, each athlete its own team, ranked by info["places"]); 0 for the
// two-team modes (1v1, 2v2, ...) that the league plays home and away.
int ranked_seats(const std::string& mode);

// Refuses, saying what to change, a tournament a ranked mode cannot play: formats other than
// round-robin, double-round-robin, swiss and knockout for N > 2 (self-play pairs two), or fewer
// entrants than seats. Two-team modes pass.
void check_ranked_tournament(const std::string& mode, const std::string& format, int entrants);

// "Every entrant meets every other in some heat", `meetings` times (1: round-robin, 2: double):
// rounds of floor(E / N) heats of N, the E mod N entrants with the most appearances resting
// (so appearances never differ by more than one), the heats of a round the best of 64 seeded
// random draws by how many pairs that have not yet met enough they bring together, until every
// pair has. Seats (lanes) within a heat are in drawn order. A pure function of its arguments.
// Throws std::invalid_argument when there are fewer entrants than seats.
std::vector<Pairing> heats(int entrants, int seats, std::uint64_t seed, int meetings = 1);

}  // namespace olympics::selfplay
