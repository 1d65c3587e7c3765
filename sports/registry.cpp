#include "registry.h"

#include <memory>
#include <stdexcept>

#include "racket/racket_sport.h"
#include "sandbox/sandbox.h"

namespace olympics::sports {
namespace {

const std::vector<std::unique_ptr<Sport>>& all_sports() {
  static const auto sports = [] {
    std::vector<std::unique_ptr<Sport>> v;
    v.push_back(std::make_unique<SandboxSport>());
    v.push_back(std::make_unique<racket::RacketSport>(/*table_tennis=*/false));
    v.push_back(std::make_unique<racket::RacketSport>(/*table_tennis=*/true));
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
