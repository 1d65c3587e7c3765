#include "catalog.h"

#include <cmath>
#include <limits>

#include "core/self_observation.h"
#include "registry.h"

namespace olympics::sports {
namespace {

nlohmann::json blocks_json(const std::vector<LayoutBlock>& blocks, bool with_bounds) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& b : blocks) {
    nlohmann::json j = {
        {"name", b.name}, {"size", b.size}, {"units", b.units}, {"meaning", b.meaning}};
    // JSON has no infinity: an unclamped block's bound is null.
    if (with_bounds) {
      const double bound = observation_bound(b);
      j["bound"] = std::isinf(bound) ? nlohmann::json(nullptr) : nlohmann::json(bound);
    }
    if (!b.fields.empty()) {
      j["fields"] = nlohmann::json::array();
      for (const auto& f : b.fields)
        j["fields"].push_back({{"name", f.name}, {"offset", f.offset}, {"size", f.size}});
    }
    out.push_back(std::move(j));
  }
  return out;
}

// The control rate a match of the mode runs at, with the default settings (a match's own: its
// scene's).
int control_hz(const Sport& sport, const std::string& mode) {
  MatchSettings settings;
  settings.mode = mode;
  return sport.create(settings)->control_hz();
}

nlohmann::json mode_json(const Sport& sport, const ModeSpec& spec) {
  const Layout l = sport.layout(spec.name);
  nlohmann::json rewards = nlohmann::json::array(), calls = nlohmann::json::array();
  for (const auto& t : l.rewards)
    rewards.push_back({{"name", t.name}, {"weight", t.weight}, {"meaning", t.meaning}});
  for (const auto& c : l.calls)
    calls.push_back({{"name", c.name}, {"meaning", c.meaning}, {"announced", c.announced}});
  return {{"name", spec.name},
          {"summary", spec.summary},
          {"slot_teams", spec.slot_teams},
          {"obs_size", l.observation_size()},
          {"action_size", l.action_size()},
          {"control_hz", control_hz(sport, spec.name)},
          {"observation", blocks_json(l.observation, true)},
          {"action", blocks_json(l.action, false)},
          {"rewards", std::move(rewards)},
          {"calls", std::move(calls)}};
}

}  // namespace

double observation_bound(const LayoutBlock& block) {
  if (block.name == kSelfBlock) return core::kObservationClamp;
  return std::numeric_limits<double>::infinity();
}

nlohmann::json describe_sport(const Sport& sport, const std::string& mode) {
  nlohmann::json settings = nlohmann::json::array();
  for (const auto& s : sport.settings()) {
    nlohmann::json setting = {{"key", s.key},
                              {"default", s.default_value},
                              {"meaning", s.meaning},
                              {"allowed", s.allowed()}};
    if (s.official) setting["official"] = *s.official;  // what "rules": "official" sets
    settings.push_back(std::move(setting));
  }
  nlohmann::json modes = nlohmann::json::array();
  if (mode.empty())
    for (const auto& spec : sport.modes().all()) modes.push_back(mode_json(sport, spec));
  else
    modes.push_back(mode_json(sport, sport.modes().at(mode)));
  return {{"name", sport.name()},
          {"summary", sport.summary()},
          {"default_time_limit_s", sport.default_time_limit_s()},
          {"control_hz", control_hz(sport, sport.modes().all().front().name)},
          {"settings", std::move(settings)},
          {"modes", std::move(modes)}};
}

nlohmann::json sport_catalog() {
  nlohmann::json sports = nlohmann::json::array();
  for (const auto& name : sport_names()) sports.push_back(describe_sport(sport_or_throw(name)));
  return {{"sports", std::move(sports)}};
}

}  // namespace olympics::sports
