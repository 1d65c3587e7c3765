// A race's places (TR 19.21-19.22, 21): finishers by time, equal times sharing a place; every
// athlete who did not finish or was disqualified after them, sharing the last place.
#pragma once

#include <optional>
#include <vector>

#include "hurdles/race_referee.h"

namespace olympics::sports::hurdles {

// One entry per athlete (nullopt: the race is not decided for it yet, counted as not finished).
std::vector<int> race_places(const std::vector<std::optional<RaceResult>>& results);

}  // namespace olympics::sports::hurdles
