#include "wire_check.h"

#include <cstring>
#include <map>
#include <stdexcept>

#include "olympics/wire_schema.hpp"

namespace olympics::protocol {
namespace {

using wire::Kind;

const wire::StructSchema* find_struct(const std::string& name) {
  static const auto by_name = [] {
    std::map<std::string, const wire::StructSchema*> m;
    for (const auto& s : wire::all_structs()) m[s.name] = &s;
    return m;
  }();
  auto it = by_name.find(name);
  return it == by_name.end() ? nullptr : it->second;
}

int fixed_size(Kind k) {
  switch (k) {
    case Kind::Int8:
    case Kind::Boolean:
    case Kind::Byte:
      return 1;
    case Kind::Int16:
      return 2;
    case Kind::Int32:
    case Kind::Float:
      return 4;
    case Kind::Int64:
    case Kind::Double:
      return 8;
    default:
      return 0;  // strings and structs: variable
  }
}

// Reads big-endian integers, as LCM writes them.
std::int64_t read_int(const std::uint8_t* p, int bytes) {
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v = (v << 8) | p[i];
  const int shift = 64 - 8 * bytes;
  return static_cast<std::int64_t>(v << shift) >> shift;  // sign-extend
}

struct Walker {
  const std::uint8_t* data;
  int size;
  int pos = 0;
  std::vector<FieldSpan>* spans = nullptr;  // collected when asked for

  [[noreturn]] void fail(const std::string& why) { throw std::invalid_argument(why); }
  int left() const { return size - pos; }

  void walk_struct(const wire::StructSchema& s, const std::string& path) {
    std::map<std::string, std::int64_t> values;  // integer fields read so far: array sizes
    for (const auto& f : s.fields) {
      const std::string where = path + f.name;
      std::int64_t count = 1;
      for (const auto& d : f.dims) {
        std::int64_t n = d.fixed;
        if (d.fixed < 0) {
          auto v = values.find(d.field);
          if (v == values.end()) fail(where + ": its size field " + d.field + " was not read");
          n = v->second;
        }
        if (n < 0) fail(where + ": negative count " + std::to_string(n));
        // The decoder sizes each inner dimension once per element of the outer ones: behind an
        // empty outer dimension an inner count allocates nothing, and is legal at any size.
        if (count == 0) continue;
        if (n > size) fail(where + ": count " + std::to_string(n) + " exceeds the message");
        count *= n;
        if (count > size)
          fail(where + ": " + std::to_string(count) + " elements exceed the message");
      }
      const int width = fixed_size(f.kind);
      if (width > 0) {
        if (count * width > left())
          fail(where + ": " + std::to_string(count) + " values do not fit the " +
               std::to_string(left()) + " bytes left");
        if (f.dims.empty() && f.kind != Kind::Float && f.kind != Kind::Double) {
          values[f.name] = read_int(data + pos, width);
          if (spans) spans->push_back({where, pos, width, false});
        }
        pos += static_cast<int>(count * width);
      } else if (f.kind == Kind::String) {
        for (std::int64_t i = 0; i < count; ++i) {
          if (left() < 4) fail(where + ": the bytes end before its length");
          const std::int64_t length = read_int(data + pos, 4);
          if (spans) spans->push_back({where, pos, 4, true});
          pos += 4;
          if (length < 1 || length > left())
            fail(where + ": string length " + std::to_string(length) + " (1.." +
                 std::to_string(left()) + " possible)");
          if (data[pos + length - 1] != 0) fail(where + ": string not NUL-terminated");
          // LCM strings are C strings: an inner NUL would decode to a longer std::string than the
          // encoder (strlen) writes back, so a relayed copy would not match what was received.
          if (std::memchr(data + pos, 0, static_cast<std::size_t>(length - 1)))
            fail(where + ": string holds a NUL before its end");
          pos += static_cast<int>(length);
        }
      } else {
        const wire::StructSchema* inner = find_struct(f.struct_type);
        if (!inner) fail(where + ": unknown type " + f.struct_type);
        for (std::int64_t i = 0; i < count; ++i) walk_struct(*inner, where + ".");
      }
    }
  }
};

}  // namespace

std::optional<std::string> wire_problem(const std::string& type, std::int64_t hash,
                                        const std::uint8_t* data, int size) {
  const wire::StructSchema* s = find_struct(type);
  if (!s) return "no message type " + type;
  if (!data || size < 8) return "fewer than the 8 bytes of a fingerprint";
  if (read_int(data, 8) != hash) return "the fingerprint is not " + type + "'s";
  Walker w{data, size, 8};
  try {
    w.walk_struct(*s, "");
  } catch (const std::invalid_argument& e) {
    return std::string(e.what());
  }
  return std::nullopt;
}

std::vector<FieldSpan> wire_fields(const std::string& type, const std::uint8_t* data, int size) {
  std::vector<FieldSpan> spans;
  const wire::StructSchema* s = find_struct(type);
  if (!s || size < 8) return spans;
  Walker w{data, size, 8, &spans};
  try {
    w.walk_struct(*s, "");
  } catch (const std::invalid_argument&) {
    return {};
  }
  return spans;
}

}  // namespace olympics::protocol
