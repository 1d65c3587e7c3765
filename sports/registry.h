// Every sport the server knows, by name. Adding a sport: its folder (with a factory
// make_<name>()) plus one line in registry.cpp. docs/sports-framework.md says how.
#pragma once

#include <string>
#include <vector>

#include "sport.h"

namespace olympics::sports {

// nullptr when unknown.
const Sport* find_sport(const std::string& name);
std::vector<std::string> sport_names();
// Throws std::invalid_argument "unknown sport "x"; known sports: a, b" when unknown.
const Sport& sport_or_throw(const std::string& name);

}  // namespace olympics::sports
