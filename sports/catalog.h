// Every sport's modes, vectors, rewards, calls and settings as one JSON document: what
// `olympics-server describe --json` prints and what the Python package ships (sports.json), so
// a client knows a mode's slots, sizes and observation bounds before any server answers.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "sport.h"

namespace olympics::sports {

// {"name", "summary", "default_time_limit_s", "control_hz", "settings": [...], "modes": [...]}
// for one sport; `mode` "" = all its modes (an unknown one throws, naming the modes). The
// control rates are those its matches run at (each mode's own, and its first mode's for the
// sport), with the default settings.
nlohmann::json describe_sport(const Sport& sport, const std::string& mode = "");
// {"sports": [describe_sport(s) for every registered sport]}
nlohmann::json sport_catalog();

// The largest magnitude an observation block can hold (the self observation is clamped to
// +-5), or infinity for a block the server does not clamp.
double observation_bound(const LayoutBlock& block);

}  // namespace olympics::sports
