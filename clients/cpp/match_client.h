// The C++ client library: request or join a match, receive observation batches, send action
// batches, get the result. It handles datagram loss (resends joins, requests and actions, drops
// duplicate observations) and sends heartbeats, so a policy loop only calls next() and act().
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "olympics/error_t.hpp"
#include "olympics/match_created_t.hpp"
#include "olympics/match_result_t.hpp"
#include "transport.h"

namespace olympics::client {

// The server refused something (its error code and message), or nothing answered in time.
class MatchError : public std::runtime_error {
 public:
  MatchError(std::string code, const std::string& message)
      : std::runtime_error(code + ": " + message), code_(std::move(code)) {}
  const std::string& code() const { return code_; }

 private:
  std::string code_;
};

struct ClientOptions {
  std::string lcm_url;  // empty: the default loopback multicast
  std::string agent_name = "agent";
  std::string policy_id;
  std::string policy_version;
  double resend_interval_s = 0.03;
  double heartbeat_interval_s = 0.5;
  // The match's server not announcing for this long (it announces every second), or announcing
  // another boot, ends the wait for the match: SERVER_GONE / SERVER_RESTARTED.
  double server_silence_s = 5.0;
  double drop_rate = 0;  // TEST ONLY: drop this share of sent datagrams
  std::uint64_t drop_seed = 1;
  // The deployment's secret file ("" = $OLYMPICS_SECRET_FILE, or none): messages are signed and
  // checked (docs/security.md).
  std::string secret_file;
};

// A league's word to a live learner: play these slots of this match.
struct Assignment {
  std::string league, learner, match_id, opponent;
  int game = 0;
  std::vector<int> slots;
};

struct MatchRequest {
  std::string sport = "sandbox";
  std::string mode = "1v1";
  std::int64_t seed = 0;
  double time_limit_s = 0;  // 0: the sport's default
  bool realtime = false;
  std::string request_id;  // clients sending the same id get the same match
  std::string server_id;   // "" = any server
  std::string options;     // the sport's settings, a JSON object ("" = defaults)
};

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

class MatchClient {
 public:
  explicit MatchClient(const ClientOptions& options = {});
  const std::string& client_id() const { return client_id_; }

  olympics::match_created_t request_match(const MatchRequest& request, double timeout_s = 10);
  // Waits for the league to assign a match to the live learner `learner` (an entrant
  // "live:<learner>"); each match is handed out once.
  Assignment wait_assignment(const std::string& learner, double timeout_s = 600);
  // Claims `slots` of a match; returns its description. Throws MatchError when refused. A client
  // may join one match after another; joining forgets the previous match.
  olympics::match_created_t join(const std::string& match_id, const std::vector<int>& slots,
                                 double timeout_s = 30);
  // The next tick's observations; nullopt once the match is over and its result is in.
  std::optional<Observation> next(double timeout_s = 60);
  // Actions for `tick`, one vector per owned slot, in slot order.
  void act(int tick, const std::vector<std::vector<float>>& actions);
  // Waits for the result after the final observation (resending what is needed to get it).
  const olympics::match_result_t& wait_result(double timeout_s = 30);
  const std::optional<olympics::match_result_t>& result() const { return result_; }
  // Errors the server addressed to this client (or to no client) since the last call.
  std::vector<olympics::error_t> take_errors();
  const olympics::match_created_t& match() const { return match_; }

 private:
  using Clock = std::chrono::steady_clock;
  void pump(Clock::time_point until);
  // Throws when the match cannot go on: a fatal error about it, or its server gone or restarted.
  void fail_if_match_lost();
  void heartbeat_if_due();
  void resend_if_due();

  ClientOptions options_;
  std::string client_id_;
  protocol::Transport transport_;
  olympics::match_created_t match_;
  std::vector<int> slots_;
  bool joined_ = false;
  int obs_subscription_ = -1;
  std::string pending_request_id_;
  std::optional<olympics::match_created_t> created_;
  std::optional<bool> join_accepted_;
  std::string join_refusal_;
  std::optional<Observation> latest_;  // newest unseen observation
  int last_returned_tick_ = -1;
  std::vector<std::uint8_t> last_action_bytes_;
  int last_action_tick_ = -1;
  std::int64_t seq_ = 0;
  std::optional<olympics::match_result_t> result_;
  std::vector<Assignment> assignments_;  // heard, not yet handed out
  std::vector<std::string> assigned_matches_;
  std::vector<olympics::error_t> errors_;
  Clock::time_point last_heartbeat_, last_send_;
  struct ServerSeen {
    Clock::time_point when;
    std::int64_t boot_us = 0;
  };
  std::map<std::string, ServerSeen> servers_;  // by id, from their announcements
  std::int64_t match_server_boot_ = 0;         // the match's server's boot when we joined
  Clock::time_point joined_at_;
  static constexpr double kMaxResendGapS = 0.25;
  static constexpr size_t kMaxQueued = 1000;  // errors, assignments kept until taken
  double resend_gap_s_ = 0.03;
};

}  // namespace olympics::client
