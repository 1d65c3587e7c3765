#include "framework/observation_writer.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace olympics::sports {

ObservationWriter::ObservationWriter(const std::vector<LayoutBlock>& blocks, std::span<float> out)
    : blocks_(blocks), out_(out) {
  int total = 0;
  for (const auto& b : blocks_) total += b.size;
  if (total != static_cast<int>(out_.size()))
    throw std::logic_error("observation of " + std::to_string(out_.size()) +
                           " floats for a layout of " + std::to_string(total));
}

void ObservationWriter::check_full() const {
  if (block_ >= 0 && written_ != blocks_[block_].size)
    throw std::logic_error("observation block \"" + blocks_[block_].name + "\" declares " +
                           std::to_string(blocks_[block_].size) + " floats, " +
                           std::to_string(written_) + " were written");
}

ObservationWriter& ObservationWriter::begin(std::string_view name) {
  check_full();
  if (block_ >= 0) offset_ += blocks_[block_].size;
  ++block_;
  if (block_ >= static_cast<int>(blocks_.size()) || blocks_[block_].name != name)
    throw std::logic_error("observation block \"" + std::string(name) + "\" written where " +
                           (block_ < static_cast<int>(blocks_.size())
                                ? "\"" + blocks_[block_].name + "\""
                                : std::string("no block")) +
                           " is declared");
  written_ = 0;
  field_ = -1;
  field_written_ = 0;
  return *this;
}

ObservationWriter& ObservationWriter::field(std::string_view name) {
  if (block_ < 0) throw std::logic_error("observation field written before any block began");
  const LayoutBlock& block = blocks_[block_];
  if (field_ >= 0 && field_written_ != block.fields[field_].size)
    throw std::logic_error("observation field \"" + block.name + "." + block.fields[field_].name +
                           "\" declares " + std::to_string(block.fields[field_].size) +
                           " floats, " + std::to_string(field_written_) + " were written");
  ++field_;
  if (field_ >= static_cast<int>(block.fields.size()) || block.fields[field_].name != name)
    throw std::logic_error(
        "observation field \"" + block.name + "." + std::string(name) + "\" written where " +
        (field_ < static_cast<int>(block.fields.size()) ? "\"" + block.fields[field_].name + "\""
                                                        : std::string("no field")) +
        " is declared");
  field_written_ = 0;
  return *this;
}

float* ObservationWriter::next(int count) {
  if (block_ < 0 || written_ + count > blocks_[block_].size)
    throw std::logic_error(block_ < 0 ? std::string("observation written before any block began")
                                      : "observation block \"" + blocks_[block_].name +
                                            "\" overfilled: it declares " +
                                            std::to_string(blocks_[block_].size) + " floats");
  const LayoutBlock& block = blocks_[block_];
  if (!block.fields.empty()) {
    if (field_ < 0)
      throw std::logic_error("observation block \"" + block.name +
                             "\" written outside its fields: begin its field \"" +
                             block.fields.front().name + "\" first");
    if (field_written_ + count > block.fields[field_].size)
      throw std::logic_error("observation field \"" + block.name + "." + block.fields[field_].name +
                             "\" overfilled: it declares " +
                             std::to_string(block.fields[field_].size) + " floats");
    field_written_ += count;
  }
  float* at = out_.data() + offset_ + written_;
  written_ += count;
  return at;
}

ObservationWriter& ObservationWriter::put(double value) {
  *next(1) = static_cast<float>(value);
  return *this;
}

ObservationWriter& ObservationWriter::put(const Eigen::Vector2d& v) {
  float* at = next(2);
  for (int i = 0; i < 2; ++i) at[i] = static_cast<float>(v[i]);
  return *this;
}

ObservationWriter& ObservationWriter::put(const Eigen::Vector3d& v) {
  float* at = next(3);
  for (int i = 0; i < 3; ++i) at[i] = static_cast<float>(v[i]);
  return *this;
}

ObservationWriter& ObservationWriter::put_clamped(const Eigen::Vector3d& v, float limit) {
  float* at = next(3);
  for (int i = 0; i < 3; ++i) at[i] = std::clamp(static_cast<float>(v[i]), -limit, limit);
  return *this;
}

std::span<float> ObservationWriter::whole_block() {
  if (block_ < 0) throw std::logic_error("observation written before any block began");
  const int size = blocks_[block_].size;
  if (written_ != 0)
    throw std::logic_error("observation block \"" + blocks_[block_].name + "\" already begun");
  float* at = out_.data() + offset_;
  written_ = size;
  return {at, static_cast<size_t>(size)};
}

void ObservationWriter::finish() const {
  check_full();
  if (block_ + 1 != static_cast<int>(blocks_.size()))
    throw std::logic_error("observation ended before block \"" + blocks_[block_ + 1].name + "\"");
}

}  // namespace olympics::sports
