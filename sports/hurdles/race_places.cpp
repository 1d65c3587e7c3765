#include "hurdles/race_places.h"

namespace olympics::sports::hurdles {

std::vector<int> race_places(const std::vector<std::optional<RaceResult>>& results) {
  auto finished = [](const std::optional<RaceResult>& r) { return r && r->finished(); };
  std::vector<int> place(results.size(), 1);
  for (size_t i = 0; i < results.size(); ++i)
    for (size_t j = 0; j < results.size(); ++j) {
      const bool j_before_i =
          finished(results[j]) && (!finished(results[i]) || results[j]->time < results[i]->time);
      if (j_before_i) ++place[i];
    }
  return place;
}

}  // namespace olympics::sports::hurdles
