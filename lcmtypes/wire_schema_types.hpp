// What the generated wire_schema.hpp describes: each message struct as its fields in encoding
// order, with the dimensions of array fields (a fixed size, or the value of an earlier field).
#pragma once

#include <string>
#include <vector>

namespace olympics::wire {

enum class Kind { Int8, Int16, Int32, Int64, Float, Double, Boolean, Byte, String, Struct };

struct Dimension {
  int fixed = -1;     // >= 0: a fixed size
  std::string field;  // else: the earlier integer field holding the size
};

struct FieldSchema {
  std::string name;
  Kind kind;
  std::string struct_type;  // Kind::Struct: which struct
  std::vector<Dimension> dims;
};

struct StructSchema {
  std::string name;
  std::vector<FieldSchema> fields;
};

}  // namespace olympics::wire
