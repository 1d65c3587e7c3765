#include "framework/referee_events.h"

#include <cmath>

namespace olympics::sports {
namespace {

double milliseconds(double t) { return std::round(t * 1000) / 1000; }

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

double tenths(double x) { return std::round(x * 10) / 10; }

nlohmann::json referee_event(const std::string& call, double t, int slot) {
  nlohmann::json e = {{"call", call}, {"t", milliseconds(t)}};
  if (slot >= 0) e["slot"] = slot;
  return e;
}

void EventLog::begin_tick(int tick) {
  tick_ = tick;
  events_ = nlohmann::json::array();
}

void EventLog::add(nlohmann::json event, double now) {
  event["tick"] = tick_;
  if (!event.contains("t")) event["t"] = milliseconds(now);
  events_.push_back(std::move(event));
}

std::optional<std::string> check_referee_event(const nlohmann::json& e, const Layout& layout,
                                               int slots, int teams, int tick) {
  if (!e.is_object()) return "not an object: " + e.dump();
  if (!e.contains("call") || !e["call"].is_string()) return "no \"call\": " + e.dump();
  const std::string call = e["call"];
  bool declared = false;
  for (const auto& c : layout.calls) declared = declared || c.name == call;
  if (!declared) return "call \"" + call + "\" is not among the sport's declared calls";
  if (!e.contains("tick") || !e["tick"].is_number_integer() || e["tick"].get<int>() != tick)
    return "\"tick\" is not " + std::to_string(tick) + ": " + e.dump();
  if (!e.contains("t") || !e["t"].is_number() || e["t"].get<double>() < 0)
    return "no time \"t\" >= 0: " + e.dump();
  for (const auto& [key, value] : e.items()) {
    const bool is_slot = key == "slot" || ends_with(key, "_slot");
    const bool is_team = key == "team" || ends_with(key, "_team");
    if (is_slot || is_team) {
      const int limit = is_slot ? slots : teams;
      // -1 means "none" in details such as culprit_slot or winner_team.
      if (!value.is_number_integer() ||
          value.get<int>() < (key == "slot" || key == "team" ? 0 : -1) || value.get<int>() >= limit)
        return "\"" + key + "\" is not a " + (is_slot ? "slot" : "team") +
               " of this match: " + e.dump();
    } else if (!value.is_primitive()) {
      return "detail \"" + key + "\" is not a number, string or boolean: " + e.dump();
    }
  }
  return std::nullopt;
}

}  // namespace olympics::sports
