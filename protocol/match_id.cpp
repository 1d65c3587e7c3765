#include "match_id.h"

namespace olympics::protocol {
namespace {
constexpr const char* kDigits = "0123456789abcdefghijklmnopqrstuvwxyz";
}

std::string boot_tag(std::int64_t boot_us) {
  auto v = static_cast<std::uint64_t>(boot_us / 1000);
  std::string out;
  do out.insert(out.begin(), kDigits[v % 36]), v /= 36;
  while (v);
  return out;
}

std::string make_match_id(const std::string& server_id, const std::string& boot_tag, long n) {
  return server_id + "-" + boot_tag + "-" + std::to_string(n);
}

std::optional<std::int64_t> match_boot_ms(const std::string& match_id) {
  const auto first = match_id.find('-');
  if (first == std::string::npos) return std::nullopt;
  const auto second = match_id.find('-', first + 1);
  if (second == std::string::npos || second == first + 1 || second - first > 14)
    return std::nullopt;
  std::int64_t v = 0;
  for (auto i = first + 1; i < second; ++i) {
    const char c = match_id[i];
    const int d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'z' ? c - 'a' + 10 : -1;
    if (d < 0) return std::nullopt;
    v = v * 36 + d;
  }
  return v;
}

}  // namespace olympics::protocol
