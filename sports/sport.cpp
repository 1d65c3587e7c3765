#include "sport.h"

#include <stdexcept>

namespace olympics::sports {

int Layout::observation_size() const {
  int n = 0;
  for (const auto& b : observation) n += b.size;
  return n;
}

int Layout::action_size() const {
  int n = 0;
  for (const auto& b : action) n += b.size;
  return n;
}

nlohmann::json merge_settings(const std::string& sport, const std::vector<SettingSpec>& specs,
                              const nlohmann::json& options) {
  nlohmann::json merged = nlohmann::json::object();
  std::string known;
  for (const auto& s : specs) {
    merged[s.key] = s.default_value;
    known += (known.empty() ? "" : ", ") + s.key;
  }
  if (known.empty()) known = "none";
  if (options.is_null()) return merged;  // no options given: the defaults
  if (!options.is_object()) throw std::invalid_argument(sport + ": settings must be a JSON object");
  for (const auto& [key, value] : options.items()) {
    if (!merged.contains(key))
      throw std::invalid_argument(sport + " has no setting \"" + key +
                                  "\"; its settings: " + known);
    const auto& def = merged[key];
    const bool both_numbers = def.is_number() && value.is_number();
    if (!both_numbers && def.type() != value.type())
      throw std::invalid_argument(sport + " setting \"" + key + "\" must be a " + def.type_name() +
                                  " like " + def.dump() + ", got " + value.dump());
    merged[key] = value;
  }
  return merged;
}

}  // namespace olympics::sports
