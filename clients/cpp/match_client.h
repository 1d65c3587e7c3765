// The C++ client library for one match at a time: request or join a match, receive observation
// batches, send action batches, get the result. It handles datagram loss (resends joins,
// requests and actions, drops duplicate observations) and sends heartbeats, so a policy loop
// only calls next() and act(). For many matches at once through one connection: VectorClient.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "connection.h"
#include "match_session.h"

namespace olympics::client {

class MatchClient {
 public:
  explicit MatchClient(const ClientOptions& options = {});
  const std::string& client_id() const { return connection_.client_id(); }
  // Errors naming this client for a match it does not hold, not acted on (docs/security.md).
  long ignored_errors() const { return connection_.ignored_errors(); }

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
  std::optional<olympics::match_result_t> result() const;
  // Errors the server addressed to this client (or to no client) since the last call.
  std::vector<olympics::error_t> take_errors() { return connection_.take_errors(); }
  const olympics::match_created_t& match() const;

 private:
  MatchSession& session(const char* what);
  Connection connection_;
  std::unique_ptr<MatchSession> session_;
};

// Requests a match through `connection` (resending until answered); throws MatchError on a
// refusal or when no server answers in `timeout_s`.
olympics::match_created_t request_match(Connection& connection, const MatchRequest& request,
                                        double timeout_s);
// Joins `slots` of a match (resending until answered); throws MatchError when refused.
olympics::match_created_t join_match(Connection& connection, const std::string& match_id,
                                     const std::vector<int>& slots, double timeout_s);

}  // namespace olympics::client
