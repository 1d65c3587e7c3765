// Where each named block of an observation lies, and each named field inside a block: the one
// layout description every client reads observations by. The server sends it with each match
// (match_created_t: block names and sizes, then each block's fields in order, names and sizes),
// built from what each sport declares where it writes its blocks (sports/sport.h LayoutBlock), so
// no client counts offsets by hand:
//
//   const ObservationLayout l = ObservationLayout::from_message(created);
//   const int ball = l.offset("ball", "position");  // the ball's position, 3 floats
//
// Header-only and free of the wire types, so that policies and in-process users (tests,
// benchmarks: from_blocks of the server's own layout) include it alone.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace olympics::client {

class ObservationLayout {
 public:
  struct Field {
    std::string name;
    int offset = 0;  // from the start of its block
    int size = 0;
  };
  struct Block {
    std::string name;
    int offset = 0;  // from the start of the observation
    int size = 0;
    std::vector<Field> fields;  // in order, tiling the block; empty where none are declared
  };

  ObservationLayout() = default;
  // Blocks by name and size, without fields.
  ObservationLayout(const std::vector<std::string>& names, const std::vector<int>& sizes)
      : ObservationLayout(names, sizes, std::vector<int>(names.size(), 0), {}, {}) {}
  // The wire's form: `field_counts[b]` of the fields (names and sizes, block after block) are
  // block b's. Throws std::invalid_argument saying what does not add up.
  ObservationLayout(const std::vector<std::string>& names, const std::vector<int>& sizes,
                    const std::vector<int>& field_counts,
                    const std::vector<std::string>& field_names,
                    const std::vector<int>& field_sizes) {
    if (names.size() != sizes.size() || names.size() != field_counts.size())
      throw std::invalid_argument(
          "observation layout: block names, sizes and field counts differ in number");
    if (field_names.size() != field_sizes.size())
      throw std::invalid_argument("observation layout: field names and sizes differ in number");
    size_t next_field = 0;
    for (size_t b = 0; b < names.size(); ++b) {
      if (sizes[b] < 0 || field_counts[b] < 0)
        throw std::invalid_argument("observation layout: block \"" + names[b] +
                                    "\" has a negative size or field count");
      Block block{names[b], total(), sizes[b], {}};
      int at = 0;
      for (int f = 0; f < field_counts[b]; ++f, ++next_field) {
        if (next_field >= field_names.size())
          throw std::invalid_argument(
              "observation layout: the blocks' field counts add up to "
              "more fields than are listed");
        if (field_sizes[next_field] <= 0)
          throw std::invalid_argument("observation layout: field \"" + names[b] + "." +
                                      field_names[next_field] + "\" has no size");
        block.fields.push_back({field_names[next_field], at, field_sizes[next_field]});
        at += field_sizes[next_field];
      }
      if (!block.fields.empty() && at != block.size)
        throw std::invalid_argument("observation layout: block \"" + names[b] + "\" holds " +
                                    std::to_string(block.size) + " floats, its fields " +
                                    std::to_string(at));
      blocks_.push_back(std::move(block));
    }
    if (next_field != field_names.size())
      throw std::invalid_argument("observation layout: " + std::to_string(field_names.size()) +
                                  " fields listed, the blocks' field counts add up to " +
                                  std::to_string(next_field));
  }

  // From anything with `name`, `size` and `fields` (each with `name` and `size`) per block: the
  // server's own layout, in process.
  template <typename Blocks>
  static ObservationLayout from_blocks(const Blocks& blocks) {
    std::vector<std::string> names, field_names;
    std::vector<int> sizes, counts, field_sizes;
    for (const auto& b : blocks) {
      names.push_back(b.name), sizes.push_back(b.size);
      counts.push_back(static_cast<int>(b.fields.size()));
      for (const auto& f : b.fields) field_names.push_back(f.name), field_sizes.push_back(f.size);
    }
    return ObservationLayout(names, sizes, counts, field_names, field_sizes);
  }
  // From a match description (match_created_t).
  template <typename MatchCreated>
  static ObservationLayout from_message(const MatchCreated& m) {
    return ObservationLayout(m.obs_block_names, m.obs_block_sizes, m.obs_block_field_counts,
                             m.obs_field_names, m.obs_field_sizes);
  }

  bool has(const std::string& block) const { return find(block) != nullptr; }
  bool has(const std::string& block, const std::string& field) const {
    const Block* b = find(block);
    return b && find(*b, field) != nullptr;
  }
  // Where block `name` starts; throws std::invalid_argument naming the blocks there are.
  int offset(const std::string& name) const { return checked(name).offset; }
  int size(const std::string& name) const { return checked(name).size; }
  // Where field `field` of block `block` starts in the observation, and its size; throws
  // std::invalid_argument naming the block's fields.
  int offset(const std::string& block, const std::string& field) const {
    const Block& b = checked(block);
    return b.offset + checked(b, field).offset;
  }
  int size(const std::string& block, const std::string& field) const {
    return checked(checked(block), field).size;
  }
  const std::vector<Block>& blocks() const { return blocks_; }
  int total() const { return blocks_.empty() ? 0 : blocks_.back().offset + blocks_.back().size; }

 private:
  const Block* find(const std::string& name) const {
    for (const auto& b : blocks_)
      if (b.name == name) return &b;
    return nullptr;
  }
  static const Field* find(const Block& block, const std::string& name) {
    for (const auto& f : block.fields)
      if (f.name == name) return &f;
    return nullptr;
  }
  const Block& checked(const std::string& name) const {
    if (const Block* b = find(name)) return *b;
    std::string known;
    for (const auto& b : blocks_) known += (known.empty() ? "" : ", ") + b.name;
    throw std::invalid_argument("the observation has no block \"" + name + "\"; its blocks: " +
                                (known.empty() ? "none (an older server?)" : known));
  }
  static const Field& checked(const Block& block, const std::string& name) {
    if (const Field* f = find(block, name)) return *f;
    std::string known;
    for (const auto& f : block.fields) known += (known.empty() ? "" : ", ") + f.name;
    throw std::invalid_argument(
        "observation block \"" + block.name + "\" has no field \"" + name +
        "\"; its fields: " + (known.empty() ? "none (an older server?)" : known));
  }

  std::vector<Block> blocks_;
};

}  // namespace olympics::client
