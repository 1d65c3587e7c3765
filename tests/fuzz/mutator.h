// Mutations of valid encoded messages for fuzzing: bit flips, rewrites of the fields a decoder
// trusts (string lengths and array counts, found by wire_fields) with hostile values, poisoned
// floats, truncation, extension and plain garbage. Deterministic for a seed.
#pragma once

#include <climits>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "wire_check.h"

namespace olympics::fuzz {

class Mutator {
 public:
  explicit Mutator(std::uint64_t seed) : rng_(seed) {}

  // A mutation of `bytes`, an encoded message of lcm type `type` ("join_t").
  std::vector<std::uint8_t> mutate(const std::string& type, std::vector<std::uint8_t> bytes) {
    if (bytes.empty()) bytes.push_back(0);
    switch (pick(7)) {
      case 0: {  // a few bit flips, the fingerprint kept so that they reach the fields
        const int flips = 1 + pick(8);
        for (int i = 0; i < flips; ++i) {
          const size_t at = bytes.size() > 8 ? 8 + pick(static_cast<int>(bytes.size()) - 8)
                                             : pick(static_cast<int>(bytes.size()));
          bytes[at] ^= static_cast<std::uint8_t>(1u << pick(8));
        }
        break;
      }
      case 1:
      case 2: {  // a length, count or integer field rewritten with a hostile value
        const auto spans =
            protocol::wire_fields(type, bytes.data(), static_cast<int>(bytes.size()));
        if (spans.empty()) break;
        const auto& f = spans[pick(static_cast<int>(spans.size()))];
        const std::int64_t hostile[] = {0,
                                        -1,
                                        INT32_MIN,
                                        INT32_MAX,
                                        1 << 30,
                                        1 << 16,
                                        static_cast<std::int64_t>(bytes.size()),
                                        2,
                                        -100000000,
                                        static_cast<std::int64_t>(rng_())};
        write_int(bytes, f.offset, f.width, hostile[pick(10)]);
        break;
      }
      case 3: {  // floats made NaN or infinite
        const float poison[] = {std::numeric_limits<float>::quiet_NaN(),
                                std::numeric_limits<float>::infinity(), -1e38f, 1e-45f};
        const int n = 1 + pick(4);
        for (int i = 0; i < n && bytes.size() >= 12; ++i) {
          const size_t at = 8 + 4 * pick(static_cast<int>((bytes.size() - 8) / 4));
          std::uint32_t v;
          std::memcpy(&v, &poison[pick(4)], 4);
          for (int k = 0; k < 4; ++k) bytes[at + k] = static_cast<std::uint8_t>(v >> (24 - 8 * k));
        }
        break;
      }
      case 4:  // truncated
        bytes.resize(pick(static_cast<int>(bytes.size())));
        break;
      case 5:  // extended with garbage
        for (int i = 0, n = 1 + pick(64); i < n; ++i)
          bytes.push_back(static_cast<std::uint8_t>(rng_()));
        break;
      default: {  // garbage, half the time behind the right fingerprint
        std::vector<std::uint8_t> junk(pick(300));
        for (auto& b : junk) b = static_cast<std::uint8_t>(rng_());
        if (pick(2) && bytes.size() >= 8 && junk.size() >= 8)
          std::copy(bytes.begin(), bytes.begin() + 8, junk.begin());
        bytes = std::move(junk);
        break;
      }
    }
    return bytes;
  }

  int pick(int n) { return n <= 1 ? 0 : static_cast<int>(rng_() % static_cast<std::uint64_t>(n)); }

 private:
  static void write_int(std::vector<std::uint8_t>& b, int at, int width, std::int64_t v) {
    for (int i = 0; i < width; ++i)
      b[at + i] = static_cast<std::uint8_t>(static_cast<std::uint64_t>(v) >> (8 * (width - 1 - i)));
  }
  std::mt19937_64 rng_;
};

}  // namespace olympics::fuzz
