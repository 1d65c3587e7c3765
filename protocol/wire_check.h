// Checks that received bytes are a well-formed LCM encoding of a message type, before lcm-gen's
// decoder sees them. Its decoders trust what they read: a string length of 0 or less makes them
// throw, a negative array count asks for an impossible allocation, and a huge one allocates
// gigabytes before noticing that the bytes run out. This walks the type's layout
// (olympics/wire_schema.hpp, generated from the .lcm files) and refuses, naming the field:
//   - a fingerprint other than the type's;
//   - a string whose length is not 1..(bytes left), that is not NUL-terminated, or that holds a
//     NUL before its end (LCM's encoder would write it back shorter);
//   - an array whose count is negative, or whose elements cannot fit the bytes left;
//   - bytes running out before the last field.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace olympics::protocol {

// What is wrong with `data` as an encoded `type` (fingerprint `hash`), or nullopt.
std::optional<std::string> wire_problem(const std::string& type, std::int64_t hash,
                                        const std::uint8_t* data, int size);

// Where the integer fields and string lengths of a well-formed encoding lie: the places a
// structure-aware fuzzer rewrites (a count, a length, a tick).
struct FieldSpan {
  std::string path;  // "match.slot_team" for a field of a nested struct
  int offset = 0, width = 0;
  bool string_length = false;
};
std::vector<FieldSpan> wire_fields(const std::string& type, const std::uint8_t* data, int size);

}  // namespace olympics::protocol
