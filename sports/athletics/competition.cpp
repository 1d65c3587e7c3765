#include "athletics/competition.h"

#include <algorithm>

#include "framework/referee_events.h"

namespace olympics::sports::athletics {

ModeTable field_event_modes(const std::string& sport, const std::string& what) {
  std::vector<ModeSpec> modes = {{"solo", {0}, "one athlete: " + what}};
  for (int n = 2; n <= kMaxAthletes; ++n) {
    std::vector<int> teams(n);
    for (int i = 0; i < n; ++i) teams[i] = i;
    modes.push_back({"competition_" + std::to_string(n), teams,
                     std::to_string(n) + " athletes, each its own team, side by side: " + what +
                         "; ranked by the rules"});
  }
  return ModeTable(sport, std::move(modes));
}

void end_competition(TickOutcome& outcome, const std::vector<int>& places,
                     const std::vector<float>& scores, const std::string& why) {
  outcome.scores = scores;
  outcome.info["places"] = places;
  const int firsts = static_cast<int>(std::count(places.begin(), places.end(), 1));
  int winner = -1;
  if (places.size() > 1 && firsts == 1)
    winner = static_cast<int>(std::find(places.begin(), places.end(), 1) - places.begin());
  outcome.end(why, winner);
}

void end_horizontal_competition(TickOutcome& outcome, const std::vector<HorizontalSeries>& series) {
  std::vector<float> best;
  for (const auto& s : series) best.push_back(static_cast<float>(s.best()));
  end_competition(outcome, places(series), best, "series_complete");
}

nlohmann::json attempt_call(const AttemptResult& result, double t, int slot, int attempt) {
  nlohmann::json e = referee_event(result.valid ? "mark" : "foul", t, slot);
  e["attempt"] = attempt;
  if (result.valid)
    e["mark"] = result.mark;
  else
    e["reason"] = result.reason;
  return e;
}

}  // namespace olympics::sports::athletics
