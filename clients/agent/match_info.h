// What a policy is told about its match before it plays: the sport and mode, the tick length,
// and where each named block of the observation lies. The server sends block names and sizes
// (match_created_t); a policy looks its blocks up by name instead of copying offsets by hand.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace olympics::client {

class ObservationLayout {
 public:
  ObservationLayout() = default;
  ObservationLayout(std::vector<std::string> names, std::vector<int> sizes)
      : names_(std::move(names)), sizes_(std::move(sizes)) {
    if (names_.size() != sizes_.size())
      throw std::invalid_argument("observation layout: names and sizes differ in number");
  }
  // From anything with `name` and `size` per block (the server's own layout, in process).
  template <typename Blocks>
  static ObservationLayout from_blocks(const Blocks& blocks) {
    ObservationLayout l;
    for (const auto& b : blocks) l.names_.push_back(b.name), l.sizes_.push_back(b.size);
    return l;
  }

  bool has(const std::string& name) const { return index(name) >= 0; }
  // Where block `name` starts; throws std::invalid_argument naming the blocks there are.
  int offset(const std::string& name) const {
    const int i = checked(name);
    int at = 0;
    for (int k = 0; k < i; ++k) at += sizes_[k];
    return at;
  }
  int size(const std::string& name) const { return sizes_[checked(name)]; }
  int total() const {
    int n = 0;
    for (int s : sizes_) n += s;
    return n;
  }

 private:
  int index(const std::string& name) const {
    for (size_t i = 0; i < names_.size(); ++i)
      if (names_[i] == name) return static_cast<int>(i);
    return -1;
  }
  int checked(const std::string& name) const {
    const int i = index(name);
    if (i >= 0) return i;
    std::string known;
    for (const auto& n : names_) known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("the observation has no block \"" + name + "\"; its blocks: " +
                                (known.empty() ? "none (an older server?)" : known));
  }

  std::vector<std::string> names_;
  std::vector<int> sizes_;
};

struct MatchInfo {
  std::string sport, mode;
  double control_dt = 0;  // seconds per tick (1 / match_created_t.control_hz)
  ObservationLayout observation;
  int action_size = 0;
};

}  // namespace olympics::client
