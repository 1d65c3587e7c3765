// One joined match as its client sees it: observations arriving on the match's channel (the
// newest unseen one kept), actions sent and resent until the next tick shows they arrived,
// heartbeats, the result, and the checks that end a match that is lost (its server gone or
// restarted, or the server saying it no longer knows the match).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "connection.h"
#include "olympics/observation_batch_t.hpp"

namespace olympics::client {

// One tick's observations for the slots this client owns, in slot order.
struct Observation {
  int tick = 0;
  std::vector<int> slots;
  std::vector<std::vector<float>> obs;
  std::vector<float> reward;
  std::vector<std::string> term_names;
  std::vector<std::vector<float>> terms;
  std::vector<bool> done, truncated;
  std::string info;  // JSON
  bool all_done() const;
};

class MatchSession {
 public:
  // `match` as the join reply described it; `slots` the ones joined.
  MatchSession(Connection& connection, olympics::match_created_t match, std::vector<int> slots);
  ~MatchSession();
  MatchSession(const MatchSession&) = delete;
  MatchSession& operator=(const MatchSession&) = delete;

  const olympics::match_created_t& match() const { return match_; }
  const std::vector<int>& slots() const { return slots_; }
  // An observation newer than the last one taken has arrived.
  bool has_observation() const { return latest_.has_value(); }
  std::optional<Observation> take_observation();
  // Actions for `tick`, one vector per owned slot, in slot order.
  void act(int tick, const std::vector<std::vector<float>>& actions);
  // The same, encoded but not sent: the caller sends it in a bundle (protocol/bundle.h) with
  // other matches' actions. Resends (maintain()) go on the match's own channel.
  const std::vector<std::uint8_t>& prepare_action(int tick,
                                                  const std::vector<std::vector<float>>& actions);
  // Heartbeats and resends when due; throws MatchError when the match is lost.
  void maintain();
  // The result, once the server has sent it.
  const olympics::match_result_t* result() const;
  // The result is in and the final observation has not come within a grace period in which
  // the last action is resent (the server answers with the final batch again): it is lost.
  bool ended_without_final_observation();

 private:
  using Clock = Connection::Clock;
  void fail_if_lost();
  // An observation batch from the match's channel or from one of this client's bundles.
  void on_observation(olympics::observation_batch_t&& batch);

  Connection& connection_;
  olympics::match_created_t match_;
  std::vector<int> slots_;
  std::optional<Observation> latest_;
  int last_taken_tick_ = -1;
  bool last_taken_done_ = false;  // the last observation taken had every slot done
  std::optional<Clock::time_point> result_seen_at_;
  std::vector<std::uint8_t> last_action_bytes_;
  int last_action_tick_ = -1;
  std::int64_t seq_ = 0;
  Clock::time_point joined_at_, last_heartbeat_, last_send_, acted_at_;
  double resend_gap_s_ = 0;  // doubles with every resend of the same action
  bool resent_ = false;      // the last action went more than once: its round trip means nothing
  std::int64_t server_boot_ = 0;  // the boot (Unix ms) of the server hosting the match
};

}  // namespace olympics::client
