// libFuzzer on every decoder the programs use (protocol::decode, i.e. the layout check then
// lcm-gen's decoder), built with AddressSanitizer and UndefinedBehaviorSanitizer by
// run_decode_fuzz.sh. The first byte picks the message type; the rest is the message. With
// --write-seeds DIR it writes one valid message of each type instead, as the starting corpus.
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include "olympics/action_batch_t.hpp"
#include "olympics/error_t.hpp"
#include "olympics/heartbeat_t.hpp"
#include "olympics/join_reply_t.hpp"
#include "olympics/join_t.hpp"
#include "olympics/league_assignment_t.hpp"
#include "olympics/match_created_t.hpp"
#include "olympics/match_request_t.hpp"
#include "olympics/match_result_t.hpp"
#include "olympics/match_start_t.hpp"
#include "olympics/observation_batch_t.hpp"
#include "olympics/server_announce_t.hpp"
#include "transport.h"

namespace oly = olympics;

namespace {

template <typename Msg>
void exercise(const std::uint8_t* data, int size) {
  if (auto m = oly::protocol::decode<Msg>(data, size)) {
    // What decodes re-encodes to a message that decodes again (no inconsistent state inside).
    const auto again = oly::protocol::encode(*m);
    const int n = static_cast<int>(again.size());
    if (auto why =
            oly::protocol::wire_problem(Msg::getTypeName(), Msg::getHash(), again.data(), n)) {
      std::fprintf(stderr, "%s re-encoded is refused: %s\n", Msg::getTypeName(), why->c_str());
      __builtin_trap();
    }
    if (!oly::protocol::decode<Msg>(again.data(), n)) __builtin_trap();
  }
  oly::protocol::wire_fields(Msg::getTypeName(), data, size);
}

template <typename Msg>
void write_seed(const std::string& dir, int type, const Msg& m) {
  auto bytes = oly::protocol::encode(m);
  bytes.insert(bytes.begin(), static_cast<std::uint8_t>(type));
  std::ofstream(dir + "/" + Msg::getTypeName(), std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const std::uint8_t* m = data + 1;
  const int n = static_cast<int>(size - 1);
  switch (data[0] % 12) {
    case 0:
      exercise<oly::action_batch_t>(m, n);
      break;
    case 1:
      exercise<oly::error_t>(m, n);
      break;
    case 2:
      exercise<oly::heartbeat_t>(m, n);
      break;
    case 3:
      exercise<oly::join_reply_t>(m, n);
      break;
    case 4:
      exercise<oly::join_t>(m, n);
      break;
    case 5:
      exercise<oly::league_assignment_t>(m, n);
      break;
    case 6:
      exercise<oly::match_created_t>(m, n);
      break;
    case 7:
      exercise<oly::match_request_t>(m, n);
      break;
    case 8:
      exercise<oly::match_result_t>(m, n);
      break;
    case 9:
      exercise<oly::match_start_t>(m, n);
      break;
    case 10:
      exercise<oly::observation_batch_t>(m, n);
      break;
    default:
      exercise<oly::server_announce_t>(m, n);
      break;
  }
  return 0;
}

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  for (int i = 1; i + 1 < *argc; ++i) {
    if (std::strcmp((*argv)[i], "--write-seeds") != 0) continue;
    const std::string dir = (*argv)[i + 1];
    oly::action_batch_t a;
    a.match_id = "srv-k-1", a.client_id = "c", a.num_slots = 2, a.slots = {0, 1};
    a.action_size = 3, a.actions = {{1, 2, 3}, {4, 5, 6}};
    write_seed(dir, 0, a);
    oly::error_t e;
    e.code = "BAD_ACTION", e.message = "m";
    write_seed(dir, 1, e);
    write_seed(dir, 2, oly::heartbeat_t{});
    oly::join_reply_t r;
    r.match.num_slots = 2, r.match.slot_team = {0, 1}, r.match.num_obs_blocks = 1;
    r.match.obs_block_names = {"self"}, r.match.obs_block_sizes = {358};
    r.match.obs_block_field_counts = {2}, r.match.num_obs_fields = 2;
    r.match.obs_field_names = {"root_height", "rest"}, r.match.obs_field_sizes = {1, 357};
    write_seed(dir, 3, r);
    oly::join_t j;
    j.num_slots = 1, j.slots = {0};
    write_seed(dir, 4, j);
    oly::league_assignment_t l;
    l.num_slots = 1, l.slots = {1};
    write_seed(dir, 5, l);
    write_seed(dir, 6, r.match);
    write_seed(dir, 7, oly::match_request_t{});
    oly::match_result_t res;
    res.num_teams = 2, res.scores = {1, 2}, res.num_slots = 1, res.slot_team = {0};
    res.agent_names = {"a"}, res.policy_ids = {"p"}, res.policy_versions = {"v"};
    write_seed(dir, 8, res);
    oly::match_start_t s;
    s.num_slots = 1, s.agent_names = {"a"};
    write_seed(dir, 9, s);
    oly::observation_batch_t o;
    o.num_slots = 1, o.slots = {0}, o.obs_size = 2, o.obs = {{1, 2}}, o.reward = {0.5f};
    o.num_terms = 1, o.term_names = {"t"}, o.terms = {{0.5f}}, o.done = {0}, o.truncated = {0};
    write_seed(dir, 10, o);
    oly::server_announce_t an;
    an.num_sports = 1, an.sports = {"sandbox"};
    write_seed(dir, 11, an);
    std::exit(0);
  }
  return 0;
}
