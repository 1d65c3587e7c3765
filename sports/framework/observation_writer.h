// Fills one slot's observation block by block and field by field, in the order its layout
// declares them, and checks each block's and field's size as it is filled: a sport cannot send a
// layout other than the one it describes (`describe`, the protocol's block and field lists).
//
//   out.begin("goals").field("attack").put(a).field("defend").put(d);
//
// A mismatch is a programming error: it throws std::logic_error naming the block or field, and
// the conformance test runs every sport's writer.
#pragma once

#include <Eigen/Core>
#include <span>
#include <string_view>
#include <vector>

#include "sport.h"

namespace olympics::sports {

class ObservationWriter {
 public:
  // `out` must hold exactly the blocks' total size.
  ObservationWriter(const std::vector<LayoutBlock>& blocks, std::span<float> out);

  // Starts block `name`, which must be the next one declared; the one before must be full.
  ObservationWriter& begin(std::string_view name);
  // Starts field `name` of the current block, which must be its next declared field; the one
  // before must be full. A block that declares fields takes values only inside them.
  ObservationWriter& field(std::string_view name);
  ObservationWriter& put(double value);
  ObservationWriter& put(const Eigen::Vector2d& v);
  ObservationWriter& put(const Eigen::Vector3d& v);
  // Each entry clamped to +-limit.
  ObservationWriter& put_clamped(const Eigen::Vector3d& v, float limit);
  // The whole current block, for writers that fill it at once (it counts as full; its fields are
  // the writer's to keep: the self block's writer and its fields share
  // core/self_observation_layout.h).
  std::span<float> whole_block();
  // Throws unless every block is full.
  void finish() const;

 private:
  void check_full() const;
  float* next(int count);

  const std::vector<LayoutBlock>& blocks_;
  std::span<float> out_;
  int block_ = -1;         // index of the current block
  int written_ = 0;        // floats written into it
  int offset_ = 0;         // where it starts
  int field_ = -1;         // index of its current field (-1: none begun)
  int field_written_ = 0;  // floats written into that field
};

}  // namespace olympics::sports
