#include "bundle.h"

#include <cstring>

#include "channels.h"
#include "version.h"

namespace olympics::protocol {
namespace {

// What a part adds to an encoded bundle: its match id (a length, the bytes and a 0), its size
// entry and its bytes.
int part_cost(const std::string& match_id, size_t part_size) {
  return 4 + static_cast<int>(match_id.size()) + 1 + 4 + static_cast<int>(part_size);
}

}  // namespace

BundleWriter::BundleWriter(std::string client_id) : client_id_(std::move(client_id)) {}

void BundleWriter::add(const std::string& match_id, std::span<const std::uint8_t> part) {
  const int cost = part_cost(match_id, part.size());
  if (bundles_.empty() || (bundles_.back().num_parts > 0 && open_size_ + cost > kMaxMessageBytes)) {
    olympics::bundle_t b;
    b.protocol_version = kProtocolVersion;
    b.client_id = client_id_;
    b.num_parts = 0;
    b.num_bytes = 0;
    std::memset(b.signature, 0, sizeof b.signature);
    bundles_.push_back(std::move(b));
    open_size_ = static_cast<int>(bundles_.back().getEncodedSize());
  }
  auto& b = bundles_.back();
  b.match_ids.push_back(match_id);
  b.part_sizes.push_back(static_cast<int>(part.size()));
  b.parts.insert(b.parts.end(), part.begin(), part.end());
  ++b.num_parts;
  b.num_bytes = static_cast<int>(b.parts.size());
  open_size_ += cost;
}

std::vector<std::vector<std::uint8_t>> BundleWriter::take() {
  std::vector<std::vector<std::uint8_t>> out;
  for (const auto& b : bundles_) {
    out.emplace_back(b.getEncodedSize());
    b.encode(out.back().data(), 0, static_cast<int>(out.back().size()));
  }
  bundles_.clear();
  return out;
}

bool for_each_part(const olympics::bundle_t& bundle,
                   const std::function<void(const std::string& match_id, const std::uint8_t* data,
                                            int size)>& part) {
  long total = 0;
  for (int size : bundle.part_sizes) {
    if (size <= 0) return false;
    total += size;
  }
  if (total != bundle.num_bytes) return false;
  long at = 0;
  for (int i = 0; i < bundle.num_parts; ++i) {
    part(bundle.match_ids[i], bundle.parts.data() + at, bundle.part_sizes[i]);
    at += bundle.part_sizes[i];
  }
  return true;
}

}  // namespace olympics::protocol
