// Decoding cannot crash: every well-formed message decodes, and bytes that are not one (a string
// length of 0 or below, an inner NUL, a negative or huge array count, truncation, random bit flips,
// another type's fingerprint) are refused without throwing and without a large allocation.
#include <gtest/gtest.h>

#include <random>

#include "olympics/action_batch_t.hpp"
#include "olympics/join_reply_t.hpp"
#include "olympics/join_t.hpp"
#include "olympics/match_request_t.hpp"
#include "olympics/observation_batch_t.hpp"
#include "transport.h"
#include "version.h"

namespace olympics::protocol {
namespace {

olympics::join_t sample_join() {
  olympics::join_t j;
  j.protocol_version = kProtocolVersion;
  j.match_id = "srv-1";
  j.client_id = "c1";
  j.agent_name = "alice";
  j.num_slots = 2;
  j.slots = {0, 1};
  return j;
}

olympics::join_reply_t sample_reply() {
  olympics::join_reply_t r;
  r.protocol_version = kProtocolVersion;
  r.match_id = "srv-1";
  r.client_id = "c1";
  r.accepted = true;
  r.match.sport = "fencing";
  r.match.num_slots = 2;
  r.match.slot_team = {0, 1};
  r.match.num_obs_blocks = 2;
  r.match.obs_block_names = {"self", "tip"};
  r.match.obs_block_sizes = {358, 6};
  r.match.obs_block_field_counts = {0, 2};
  r.match.num_obs_fields = 2;
  r.match.obs_field_names = {"position", "velocity"};
  r.match.obs_field_sizes = {3, 3};
  r.match.options = "{}";
  return r;
}

// Overwrites the 4 bytes at `at` with `value`, big-endian as LCM writes.
void put_int32(std::vector<std::uint8_t>& b, int at, std::int32_t value) {
  for (int i = 0; i < 4; ++i) b[at + i] = static_cast<std::uint8_t>(value >> (24 - 8 * i));
}

template <typename Msg>
int field_offset(const std::vector<std::uint8_t>& bytes, const std::string& path) {
  for (const auto& f :
       wire_fields(Msg::getTypeName(), bytes.data(), static_cast<int>(bytes.size())))
    if (f.path == path) return f.offset;
  ADD_FAILURE() << "no field " << path;
  return 0;
}

TEST(Decode, WellFormedMessagesDecode) {
  const auto join = encode(sample_join());
  auto j = decode<olympics::join_t>(join.data(), static_cast<int>(join.size()));
  ASSERT_TRUE(j);
  EXPECT_EQ(j->agent_name, "alice");
  EXPECT_EQ(j->slots, (std::vector<int>{0, 1}));
  const auto reply = encode(sample_reply());
  auto r = decode<olympics::join_reply_t>(reply.data(), static_cast<int>(reply.size()));
  ASSERT_TRUE(r);
  EXPECT_EQ(r->match.obs_block_names[1], "tip");
  EXPECT_EQ(r->match.obs_field_names, (std::vector<std::string>{"position", "velocity"}));
}

TEST(Decode, ZeroOrNegativeStringLengthsAreRefused) {
  for (std::int32_t length : {0, -1, -5, INT32_MIN}) {
    auto b = encode(sample_join());
    put_int32(b, field_offset<olympics::join_t>(b, "agent_name"), length);
    EXPECT_FALSE(decode<olympics::join_t>(b.data(), static_cast<int>(b.size()))) << length;
    EXPECT_TRUE(
        wire_problem("join_t", olympics::join_t::getHash(), b.data(), static_cast<int>(b.size()))
            ->find("agent_name") != std::string::npos);
  }
}

// Found by tests/fuzz: LCM's decoder keeps an inner NUL that its encoder (strlen) drops, so such a
// message would not survive being relayed. It is refused on arrival instead.
TEST(Decode, StringsWithAnInnerNulAreRefused) {
  auto b = encode(sample_join());
  const int at = field_offset<olympics::join_t>(b, "agent_name") + 4;  // after the length
  b[at + 2] = 0;                                                       // "al\0ce"
  EXPECT_FALSE(decode<olympics::join_t>(b.data(), static_cast<int>(b.size())));
  const auto why =
      wire_problem("join_t", olympics::join_t::getHash(), b.data(), static_cast<int>(b.size()));
  ASSERT_TRUE(why);
  EXPECT_NE(why->find("agent_name: string holds a NUL"), std::string::npos) << *why;
}

TEST(Decode, NegativeAndHugeArrayCountsAreRefusedWithoutAllocating) {
  for (std::int32_t count : {-1, INT32_MIN, 1 << 30, INT32_MAX}) {
    auto b = encode(sample_join());
    put_int32(b, field_offset<olympics::join_t>(b, "num_slots"), count);
    EXPECT_FALSE(decode<olympics::join_t>(b.data(), static_cast<int>(b.size()))) << count;
    auto r = encode(sample_reply());
    put_int32(r, field_offset<olympics::join_reply_t>(r, "match.num_obs_blocks"), count);
    EXPECT_FALSE(decode<olympics::join_reply_t>(r.data(), static_cast<int>(r.size()))) << count;
  }
  // A count larger than the message: the action batch claims 100000 slots of 69 floats.
  olympics::action_batch_t a;
  a.protocol_version = kProtocolVersion;
  a.match_id = "m", a.client_id = "c", a.num_slots = 1, a.slots = {0}, a.action_size = 2;
  a.actions = {{0.5f, 0.5f}};
  auto b = encode(a);
  put_int32(b, field_offset<olympics::action_batch_t>(b, "num_slots"), 100000);
  EXPECT_FALSE(decode<olympics::action_batch_t>(b.data(), static_cast<int>(b.size())));
}

// Found by tests/fuzz: an action batch with no slots and a large action_size is what LCM's own
// encoder writes for an empty batch; refusing it would refuse a relayed copy of a message we took.
// A huge slot count with an empty action_size is still refused.
TEST(Decode, InnerCountsBehindAnEmptyOuterArrayAreLegal) {
  olympics::action_batch_t a;
  a.protocol_version = kProtocolVersion;
  a.match_id = "m", a.client_id = "c", a.num_slots = 0, a.action_size = 5000;
  const auto empty = encode(a);
  ASSERT_LT(empty.size(), 5000u);
  EXPECT_TRUE(decode<olympics::action_batch_t>(empty.data(), static_cast<int>(empty.size())));
  a.action_size = 0;
  auto b = encode(a);
  put_int32(b, field_offset<olympics::action_batch_t>(b, "num_slots"), 1 << 30);
  EXPECT_FALSE(decode<olympics::action_batch_t>(b.data(), static_cast<int>(b.size())));
}

TEST(Decode, TruncationAtEveryByteAndAnotherTypeAreRefused) {
  const auto b = encode(sample_reply());
  for (int n = 0; n < static_cast<int>(b.size()); ++n)
    EXPECT_FALSE(decode<olympics::join_reply_t>(b.data(), n)) << n << " bytes";
  const auto j = encode(sample_join());
  EXPECT_FALSE(decode<olympics::match_request_t>(j.data(), static_cast<int>(j.size())));
  EXPECT_FALSE(decode<olympics::join_t>(nullptr, 0));
}

TEST(Decode, RandomBitFlipsNeverCrash) {
  std::mt19937 rng(7);
  const std::vector<std::vector<std::uint8_t>> seeds = {encode(sample_join()),
                                                        encode(sample_reply())};
  int decoded = 0, refused = 0;
  for (int i = 0; i < 20000; ++i) {
    auto b = seeds[i % 2];
    const int flips = 1 + static_cast<int>(rng() % 4);
    for (int f = 0; f < flips; ++f)
      b[rng() % b.size()] ^= static_cast<std::uint8_t>(1u << (rng() % 8));
    // Keep the fingerprint half the time, so the flips reach the fields.
    if (i % 4 < 2) std::copy(seeds[i % 2].begin(), seeds[i % 2].begin() + 8, b.begin());
    const bool ok =
        i % 2 == 0
            ? decode<olympics::join_t>(b.data(), static_cast<int>(b.size())).has_value()
            : decode<olympics::join_reply_t>(b.data(), static_cast<int>(b.size())).has_value();
    (ok ? decoded : refused)++;
  }
  EXPECT_GT(decoded, 0) << "flips inside values still decode";
  EXPECT_GT(refused, 0);
}

}  // namespace
}  // namespace olympics::protocol
