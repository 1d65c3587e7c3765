#include "bundle.h"

#include <gtest/gtest.h>

#include "channels.h"
#include "transport.h"

namespace olympics::protocol {
namespace {

std::string match_name(int i) {
  std::string name = "m";
  name += std::to_string(i);  // (not "m" + ...: GCC 12's -Wrestrict false positive)
  return name;
}

std::vector<std::uint8_t> part_of(int size, std::uint8_t fill) {
  return std::vector<std::uint8_t>(static_cast<size_t>(size), fill);
}

// Every part of every bundle, in order: (match id, bytes).
std::vector<std::pair<std::string, std::vector<std::uint8_t>>> unpack(
    const std::vector<std::vector<std::uint8_t>>& bundles) {
  std::vector<std::pair<std::string, std::vector<std::uint8_t>>> parts;
  for (const auto& bytes : bundles) {
    auto bundle = decode<olympics::bundle_t>(bytes.data(), static_cast<int>(bytes.size()));
    EXPECT_TRUE(bundle);
    if (!bundle) continue;
    EXPECT_EQ(bundle->client_id, "c1");
    EXPECT_TRUE(for_each_part(*bundle, [&](const std::string& id, const std::uint8_t* d, int n) {
      parts.emplace_back(id, std::vector<std::uint8_t>(d, d + n));
    }));
  }
  return parts;
}

TEST(Bundle, PartsComeOutAsTheyWentInEachBundleUnderADatagram) {
  BundleWriter writer("c1");
  EXPECT_TRUE(writer.empty());
  // 40 parts of 5 KB: 200 KB, so at least four bundles.
  for (int i = 0; i < 40; ++i)
    writer.add(match_name(i), part_of(5000, static_cast<std::uint8_t>(i)));
  const auto bundles = writer.take();
  EXPECT_TRUE(writer.empty());
  EXPECT_GE(bundles.size(), 4u);
  EXPECT_LE(bundles.size(), 5u) << "bundles are filled, not one part each";
  for (const auto& b : bundles) EXPECT_LE(b.size(), static_cast<size_t>(kMaxMessageBytes));
  const auto parts = unpack(bundles);
  ASSERT_EQ(parts.size(), 40u);
  for (int i = 0; i < 40; ++i) {
    EXPECT_EQ(parts[i].first, match_name(i));
    EXPECT_EQ(parts[i].second, part_of(5000, static_cast<std::uint8_t>(i)));
  }
}

TEST(Bundle, APartBiggerThanADatagramTravelsAlone) {
  BundleWriter writer("c1");
  writer.add("small", part_of(100, 1));
  writer.add("huge", part_of(kMaxMessageBytes + 10, 2));
  writer.add("after", part_of(100, 3));
  const auto parts = unpack(writer.take());
  ASSERT_EQ(parts.size(), 3u);
  EXPECT_EQ(parts[1].second.size(), static_cast<size_t>(kMaxMessageBytes + 10));
}

TEST(Bundle, SizesThatDoNotAddUpAreRefusedBeforeAnyPart) {
  olympics::bundle_t b{};
  b.protocol_version = 5;
  b.num_parts = 2;
  b.match_ids = {"a", "b"};
  b.part_sizes = {3, 3};
  b.num_bytes = 5;
  b.parts = {1, 2, 3, 4, 5};
  int calls = 0;
  EXPECT_FALSE(for_each_part(b, [&](const std::string&, const std::uint8_t*, int) { ++calls; }));
  b.part_sizes = {5, 0};  // an empty part
  EXPECT_FALSE(for_each_part(b, [&](const std::string&, const std::uint8_t*, int) { ++calls; }));
  b.part_sizes = {-1, 6};
  EXPECT_FALSE(for_each_part(b, [&](const std::string&, const std::uint8_t*, int) { ++calls; }));
  EXPECT_EQ(calls, 0);
  b.part_sizes = {2, 3};
  EXPECT_TRUE(for_each_part(b, [&](const std::string&, const std::uint8_t*, int) { ++calls; }));
  EXPECT_EQ(calls, 2);
}

}  // namespace
}  // namespace olympics::protocol
