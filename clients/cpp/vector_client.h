// Many matches at once through one connection: the client a trainer uses. Each of num_envs
// environments is a match of the same sport and mode in which this client plays the same slots
// (its agents); observations, rewards and flags come as flat arrays [env][agent][...]. A match
// that ends is replaced at once by the environment's next one (same request, next seed), so the
// arrays always hold a live match per environment.
//
// Sync: step() sends every environment's actions and returns when every one has its next
// observation. Async (EnvPool's send/recv): send() the actions of some environments, recv()
// whichever have their next observation, at least min_ready of them.
//
// Seeds: environment e's k-th match has seed base_seed + k * num_envs + e, so a run with one
// environment per process plays the same matches as one vector client (tested).
// Request ids: "<request_prefix>-<e>-<k>"; an opponent process requesting the same id meets
// this client's match (when this client does not own every slot). As a league's live learner
// (VectorSettings::learner) it plays the matches the league assigns instead.
#pragma once

#include <deque>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "connection.h"
#include "match_session.h"

namespace olympics::client {

struct VectorSettings {
  int num_envs = 1;
  MatchRequest request;        // sport, mode, settings, server; request.seed = the base seed
  std::vector<int> slots;      // played in every match; empty = every slot of the mode
  std::string request_prefix;  // "" = the client id
  double timeout_s = 60;       // nothing heard from an environment's match for this long: error
  // Play what a league assigns to its entrant live:<learner> instead of requesting matches:
  // each environment takes the next assignment (its slots, as many as `slots` has) when its
  // match ends, and waits (without the timeout) while none is there.
  std::string learner;
};

// One tick of every environment that was ready, in the order of `envs`.
struct VectorBatch {
  std::vector<int> envs;                            // which environments these rows are
  std::vector<float> obs;                           // [envs][agents][obs_size]
  std::vector<float> reward;                        // [envs][agents]
  std::vector<float> terms;                         // [envs][agents][term count]
  std::vector<std::uint8_t> terminated, truncated;  // [envs][agents]
  // The environment's match ended on this tick and was replaced: obs holds the next match's
  // first observation and final_obs the ended match's last one (zeros elsewhere).
  std::vector<std::uint8_t> episode_over;  // [envs]
  std::vector<float> final_obs;            // [envs][agents][obs_size]
  std::vector<int> tick;                   // [envs]
};

class VectorClient {
 public:
  VectorClient(const ClientOptions& options, VectorSettings settings);
  ~VectorClient();

  int num_envs() const { return settings_.num_envs; }
  int num_agents() const { return static_cast<int>(slots_.size()); }
  const std::vector<int>& slots() const { return slots_; }
  int obs_size() const { return obs_size_; }
  int action_size() const { return action_size_; }
  const std::vector<std::string>& term_names() const { return term_names_; }
  const std::string& client_id() const { return connection_.client_id(); }
  // Errors naming this client for a match it does not hold, not acted on (docs/security.md).
  long ignored_errors() const { return connection_.ignored_errors(); }

  // The batches returned are the client's own arrays, valid until its next reset, step or recv.
  // Starts every environment's first match and returns their first observations.
  const VectorBatch& reset();
  // Async: starts every environment's first match; recv() returns them as they begin.
  void start();
  // Every environment's actions [envs][agents][action_size]; their next observations.
  const VectorBatch& step(std::span<const float> actions);
  // Async: actions [envs.size()][agents][action_size] for these environments.
  void send(std::span<const int> envs, std::span<const float> actions);
  // The environments whose next observation has come since their send: at least min_ready of
  // them, or (timeout_s >= 0) whatever has come when timeout_s has passed, maybe none.
  const VectorBatch& recv(int min_ready, double timeout_s = -1);
  // Results of the matches that ended since the last call.
  std::vector<olympics::match_result_t> take_results();
  // The match an environment plays now.
  const olympics::match_created_t& match(int env) const;

 private:
  struct Env;
  void start_next_match(Env& env);
  void advance(Env& env, Connection::Clock::time_point now, bool maintain);
  void collect_results();
  void fill(VectorBatch& batch, size_t row, Env& env);
  const VectorBatch& take_ready();

  Connection connection_;
  VectorSettings settings_;
  std::vector<int> slots_;
  int obs_size_ = 0, action_size_ = 0;
  std::vector<std::string> term_names_;
  std::vector<std::unique_ptr<Env>> envs_;
  // Ended matches whose result has not come yet (kept to resend and to hear it).
  struct Ending {
    std::unique_ptr<MatchSession> session;
    Connection::Clock::time_point since;
  };
  std::deque<Ending> ending_;
  std::vector<olympics::match_result_t> results_;
  VectorBatch batch_;  // what reset, step and recv return
};

}  // namespace olympics::client
