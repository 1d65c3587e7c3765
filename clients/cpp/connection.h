// What a client of the protocol has once, however many matches it plays: the LCM transport
// (signed with the deployment secret when one is given), its client id, and what it has heard on
// the control channels — servers' announcements, answers to its requests and joins, errors
// addressed to it, results of its matches and league assignments. Each match played through it
// is a MatchSession (match_session.h); MatchClient plays one at a time, VectorClient many.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "olympics/error_t.hpp"
#include "olympics/match_created_t.hpp"
#include "olympics/match_request_t.hpp"
#include "olympics/match_result_t.hpp"
#include "olympics/observation_batch_t.hpp"
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

struct JoinReply {
  bool accepted = false;
  std::string reason;  // why not
  olympics::match_created_t match;
};

class Connection {
 public:
  using Clock = std::chrono::steady_clock;
  explicit Connection(const ClientOptions& options);
  const std::string& client_id() const { return client_id_; }
  const ClientOptions& options() const { return options_; }
  protocol::Transport& transport() { return transport_; }

  // Handles at most one message, waiting until `until` but at most 10 ms.
  void pump(Clock::time_point until);
  // Handles every message already waiting, without blocking.
  void drain();

  // Requests: send (again, until answered) and collect the server's answer or refusal.
  static olympics::match_request_t request_message(const MatchRequest& r,
                                                   const std::string& request_id);
  void send_request(const olympics::match_request_t& request);
  std::optional<olympics::match_created_t> take_created(const std::string& request_id);
  // An error the server sent about this request (its message names the request id), taken
  // from the queue.
  std::optional<olympics::error_t> take_request_error(const std::string& request_id);

  // Joins: send (again, until answered) and collect the reply. From the first join on, the
  // match's observation batches are kept for its session (on_observations): the server sends
  // the first one right behind the join reply, before a session can exist to take it.
  void send_join(const std::string& match_id, const std::vector<int>& slots);
  std::optional<JoinReply> take_join_reply(const std::string& match_id);
  // An error that ends any hope for this match: UNKNOWN_MATCH, STORE_FAILED (and, before the
  // join is accepted, UPGRADE). Never UNAUTHENTICATED: that hint names nobody and anyone can
  // send it, so it is only reported (silence_hint()).
  std::optional<olympics::error_t> fatal_error(const std::string& match_id,
                                               bool joining = false) const;

  // Results of matches this client plays (watch first); forget() when done with one.
  void watch(const std::string& match_id);
  const olympics::match_result_t* result(const std::string& match_id) const;
  void forget(const std::string& match_id);

  // The newest boot a server announced, and when it last announced it; nullopt if never heard.
  // An announcement of an earlier boot (a replay of a stopped process's) changes nothing.
  struct ServerSeen {
    Clock::time_point when;
    std::int64_t boot_us = 0;
  };
  std::optional<ServerSeen> server(const std::string& server_id) const;

  // Observation batches of a joined match, from its own channel or from this client's bundles
  // (a server bundles them once the client sends its actions in bundles): those that came
  // since the join go to `handler` at once, in order, later ones as they come. One handler per
  // match; forget_observations() when done with it.
  using ObservationHandler = std::function<void(olympics::observation_batch_t&&)>;
  void on_observations(const std::string& match_id, ObservationHandler handler);
  void forget_observations(const std::string& match_id);

  // How long a match session waits for the answer to its action before sending it again: the
  // options' resend_interval_s, or twice the longest round trip of the last second where that
  // is longer. A client stepping many matches at once gets its answers over tens of ms (a
  // server worker steps its matches one after another); resending sooner only adds load. (A
  // smoothed mean, as TCP keeps, fails here: the round trips of one step are spread evenly up
  // to the last match's, and every match above the mean would be resent.)
  double resend_interval_s() const;
  // A round trip measured by a session: action sent (not resent) to the next observation.
  void note_round_trip(double seconds);

  std::optional<Assignment> take_assignment(const std::string& learner);
  // Errors the server addressed to this client (or to its requests) since the last call.
  std::vector<olympics::error_t> take_errors();
  // Why nothing may be answering, for a TIMEOUT's message ("" when nothing suggests it): with a
  // secret, messages that failed the signature check (servers with another secret, or none);
  // without one, signed messages heard (servers with a secret); either way, a server's
  // UNAUTHENTICATED hint (our joins or requests failed its check). Only words: an outsider can
  // send all of these too, so nothing is decided on them. The same is printed on stderr once,
  // within seconds, while the first request or join of this client goes unanswered.
  std::string silence_hint() const;
  // Errors that named this client with a match it neither joined nor plays: ignored.
  long ignored_errors() const { return ignored_errors_; }

 private:
  ClientOptions options_;
  std::string client_id_;
  protocol::Transport transport_;
  std::set<std::string> pending_requests_;
  std::map<std::string, olympics::match_created_t> created_;                // by request id
  std::map<std::string, JoinReply> join_replies_;                           // by match id
  std::map<std::string, std::optional<olympics::match_result_t>> watched_;  // by match id
  std::deque<olympics::error_t> errors_;
  long ignored_errors_ = 0;
  void on_error(const olympics::error_t& e);
  // Signs of a secret mismatch (silence_hint()), and whether they were reported on stderr.
  long authentication_hints_ = 0;  // UNAUTHENTICATED hints heard
  long signed_but_unchecked_ = 0;  // signed messages heard without a secret
  bool answered_ = false;          // a request or join of ours was answered
  std::optional<Clock::time_point> first_sent_;
  bool mismatch_reported_ = false;
  void report_mismatch_if_stuck();
  std::deque<Assignment> assignments_;  // heard, not yet handed out
  std::set<std::string> assigned_matches_;
  std::map<std::string, ServerSeen> servers_;  // by id, from their announcements
  double longest_round_trip_s_ = 0;            // decays by e every second
  Clock::time_point longest_round_trip_at_;
  struct ObservationRoute {
    int subscription = -1;       // the match's own channel
    ObservationHandler handler;  // none yet: batches are held
    std::deque<olympics::observation_batch_t> held;
  };
  std::map<std::string, ObservationRoute> observation_routes_;  // by match id, from the join
  void listen_for_observations(const std::string& match_id);
  void on_observation_message(const std::string& match_id, const std::uint8_t* data, int size);
  // LCM's multi-port provider (mpudpm://): a subscription per match's channel, not a pattern.
  const bool exact_observation_channels_;
  void deliver(const std::string& match_id, olympics::observation_batch_t&& batch);
  static constexpr size_t kMaxQueued = 1000;  // errors, assignments kept until taken
  static constexpr size_t kMaxHeld = 8;       // observation batches held for a session to come
};

std::chrono::steady_clock::duration seconds(double s);

}  // namespace olympics::client
