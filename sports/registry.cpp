#include "registry.h"

#include <memory>
#include <stdexcept>

namespace olympics::sports {

// The registry: one line per sport, naming the factory its folder defines
// (std::unique_ptr<Sport> make_<name>() in namespace olympics::sports). Every line ends in a
// backslash, so a new sport is one added line.
// clang-format off
#define OLYMPICS_SPORTS(X) \
  X(sandbox)               \
  X(tennis)                \
  X(table_tennis)          \
  X(fencing)               \
  X(boxing)                \
  X(soccer)                \
  X(basketball)            \
  X(long_jump)             \
  X(high_jump)             \
  X(javelin)               \
  X(hurdles)               \
  X(golf)                  \
  /* the list's end */
// clang-format on

#define OLYMPICS_DECLARE_SPORT(name) std::unique_ptr<Sport> make_##name();
OLYMPICS_SPORTS(OLYMPICS_DECLARE_SPORT)
#undef OLYMPICS_DECLARE_SPORT

namespace {

const std::vector<std::unique_ptr<Sport>>& all_sports() {
  static const auto sports = [] {
    std::vector<std::unique_ptr<Sport>> v;
#define OLYMPICS_MAKE_SPORT(name) v.push_back(make_##name());
    OLYMPICS_SPORTS(OLYMPICS_MAKE_SPORT)
#undef OLYMPICS_MAKE_SPORT
    return v;
  }();
  return sports;
}

}  // namespace

const Sport* find_sport(const std::string& name) {
  for (const auto& s : all_sports())
    if (s->name() == name) return s.get();
  return nullptr;
}

std::vector<std::string> sport_names() {
  std::vector<std::string> names;
  for (const auto& s : all_sports()) names.push_back(s->name());
  return names;
}

const Sport& sport_or_throw(const std::string& name) {
  if (const Sport* s = find_sport(name)) return *s;
  std::string known;
  for (const auto& n : sport_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown sport \"" + name + "\"; known sports: " + known);
}

}  // namespace olympics::sports
