// One shape for every referee call of every sport: each tick's calls go to the observation's
// info["events"] and to the result, and viewers, agents and tests read them the same way.
//
//   {"call": "fall", "tick": 412, "t": 13.725, "slot": 1, ...details}
//
// - "call": one of the calls the sport declares (Layout::calls), e.g. "fall", "point", "touch";
// - "tick": the tick whose step made the call; "t": seconds into the match, at the physics step
//   where it happened (ms precision; several calls can share a tick);
// - "slot" / "team", and any detail key ending in "_slot" / "_team" ("winner_team",
//   "culprit_slot"): a slot or team of this match;
// - other details: numbers, strings, booleans.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "sport.h"

namespace olympics::sports {

// A detail rounded to a tenth (a force in N, a time in s, a spot in m), as events record them.
double tenths(double x);

// A call at `t` seconds (slot -1: no particular player); add details before logging it.
nlohmann::json referee_event(const std::string& call, double t, int slot = -1);

// The calls of the tick being stepped.
class EventLog {
 public:
  void begin_tick(int tick);
  // Stamps the tick; an event without "t" happened at `now`.
  void add(nlohmann::json event, double now);
  const nlohmann::json& events() const { return events_; }

 private:
  int tick_ = 0;
  nlohmann::json events_ = nlohmann::json::array();
};

// What is wrong with `event` against the schema above, or nullopt when nothing is.
std::optional<std::string> check_referee_event(const nlohmann::json& event, const Layout& layout,
                                               int slots, int teams, int tick);

}  // namespace olympics::sports
