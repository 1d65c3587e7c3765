// What the field events' competitions share: their modes (one athlete, or 2 to 8 each its own
// team, one slot each) and how a finished series becomes the match's outcome (every athlete's
// place; the single first place wins).
#pragma once

#include <string>
#include <vector>

#include "athletics/attempt_series.h"
#include "sport.h"

namespace olympics::sports::athletics {

inline constexpr int kMaxAthletes = 8;

// "solo", then "competition_2" ... "competition_8": N athletes, each its own team.
ModeTable field_event_modes(const std::string& sport, const std::string& what);

// Ends the match: scores per team (= per athlete) and info["places"] (1 = first, shared places
// for ties); the winner is the one athlete in first place, if only one is.
void end_competition(TickOutcome& outcome, const std::vector<int>& places,
                     const std::vector<float>& scores, const std::string& why);

// The same when every horizontal series (long jump, throws) is complete: scores the best marks,
// places by TR 25.22, reason series_complete.
void end_horizontal_competition(TickOutcome& outcome, const std::vector<HorizontalSeries>& series);

// Every athlete's series, in slot order, from a match's athletes (each with a `series` member).
template <typename Athletes>
std::vector<HorizontalSeries> series_of(const Athletes& athletes) {
  std::vector<HorizontalSeries> series;
  for (const auto& a : athletes) series.push_back(a.series);
  return series;
}

// The call for a decided attempt of a horizontal event at match time `t`: "mark" with its mark,
// or "foul" with its reason, and which attempt it was.
nlohmann::json attempt_call(const AttemptResult& result, double t, int slot, int attempt);

}  // namespace olympics::sports::athletics
