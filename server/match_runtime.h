// One match on the server: joining, the lockstep or real-time tick loop, loss handling,
// forfeits, and what it leaves behind (result, replay). Driven by one worker thread at a time.
//
// Sync mode: tick t waits for every client's action for t, republishing tick t's observation to
// the clients still missing every `resend_interval_s`, up to `action_deadline_s`; then missing
// actions repeat the previous one. Realtime mode: the clock ticks at the control rate (30 Hz);
// whatever arrived since the last tick applies, late actions apply to the next tick. In both, a
// client that misses `max_missed_ticks` ticks in a row, or is silent for `silent_timeout_s`,
// forfeits.
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "observation_outbox.h"
#include "olympics/action_batch_t.hpp"
#include "olympics/heartbeat_t.hpp"
#include "olympics/join_t.hpp"
#include "olympics/match_created_t.hpp"
#include "olympics/match_result_t.hpp"
#include "olympics/observation_batch_t.hpp"
#include "replay.h"
#include "results_store.h"
#include "scene_recorder.h"
#include "sport.h"
#include "traffic_log.h"
#include "transport.h"

namespace olympics::server {

struct RuntimeSettings {
  double action_deadline_s = 1.0;
  int max_missed_ticks = 5;
  double resend_interval_s = 0.03;
  double silent_timeout_s = 5.0;
  double join_timeout_s = 60.0;
};

struct MatchIdentity {
  std::string match_id;
  std::string server_id;
  std::string sport;
  sports::MatchSettings settings;
  bool realtime = false;
};

class MatchRuntime {
 public:
  using Clock = std::chrono::steady_clock;

  MatchRuntime(MatchIdentity identity, RuntimeSettings settings,
               std::unique_ptr<sports::SportMatch> game, protocol::Transport& transport,
               std::unique_ptr<TrafficLog> log = nullptr);

  const olympics::match_created_t& description() const { return description_; }
  const std::string& match_id() const { return identity_.match_id; }

  // A raw message from this match's channels (join, actions, heartbeat); `bundled`: an action
  // batch that came in a client's bundle, whose answers then go to `outbox`.
  void handle(const std::string& channel, const std::vector<std::uint8_t>& bytes,
              Clock::time_point now, bool bundled = false);
  // Where observations for bundling clients go (the worker's outbox); none: each is sent alone.
  void set_outbox(ObservationOutbox* outbox) { outbox_ = outbox; }
  // Advances timers; returns when it next needs to be polled.
  Clock::time_point poll(Clock::time_point now);

  bool finished() const { return finished_; }
  void publish_result();
  // The last observation batch each client was sent (by client id): a client that lost it gets
  // it again, with the result, for any message it sends about the finished match.
  const std::map<std::string, olympics::observation_batch_t>& final_batches() const {
    return final_batches_;
  }
  const olympics::match_result_t& result() const { return result_; }
  StoredMatch stored_result() const;
  // Who plays which slot (agents, policies), once every slot is claimed.
  std::vector<StoredParticipant> participants() const;
  // True once, the first time it is asked after the match started: the host notes the players.
  bool take_started();
  std::vector<std::string> client_ids() const;
  Replay replay() const;
  // Record the scene track (for viewers) from the start of play; call before it starts.
  void record_scene(std::unique_ptr<SceneRecorder> recorder) { scene_ = std::move(recorder); }

 private:
  enum class Phase { Joining, Running, Finished };
  struct Client {
    std::string id, agent, policy, policy_version;
    std::vector<int> slots;
    Clock::time_point last_heard;
    int missed_in_row = 0;
    bool acted_this_tick = false;
    bool bundled = false;  // its last actions came in a bundle: so do its observations
    std::int64_t seq = 0;
    // Answers to what it sends beyond the tick loop (errors, observations shown again): at most
    // kAnswersPerS a second, in bursts of as many (a token bucket).
    double answer_tokens = kAnswersPerS;
    Clock::time_point answer_at{};
  };
  static constexpr double kAnswersPerS = 20;
  // Whether client c may be answered now (counts it if so).
  bool may_answer(int c, Clock::time_point now);

  void on_join(const olympics::join_t& join, Clock::time_point now);
  void on_actions(const olympics::action_batch_t& batch, Clock::time_point now, bool bundled);
  void on_heartbeat(const olympics::heartbeat_t& beat, Clock::time_point now);
  void start(Clock::time_point now);
  void advance(Clock::time_point now);
  void publish_observations(const std::vector<int>& clients);
  void finish(Clock::time_point now);
  void begin_scene();
  std::vector<std::string> slot_agents() const;  // once every slot is claimed
  nlohmann::json identity_header(const std::vector<std::string>& agents) const;
  // Runs a recorder step; a recorder that fails (disk full) is dropped, the match goes on.
  template <typename Step>
  void record(Step step);
  void forfeit(int client, const std::string& why, Clock::time_point now);
  void error(const std::string& client_id, const std::string& code, const std::string& message);
  int client_index(const std::string& client_id) const;
  bool still_playing(const Client& k) const;
  std::vector<int> all_clients() const;
  // Publishes `msg`, written to the match's LCM log first; `log_whole`: and the log flushed to
  // disk before it goes out (whoever hears it may read the log at once).
  template <typename Msg>
  void send(const std::string& channel, const Msg& msg, bool log_whole = false);

  MatchIdentity identity_;
  RuntimeSettings settings_;
  std::unique_ptr<sports::SportMatch> game_;
  protocol::Transport& transport_;
  std::unique_ptr<TrafficLog> log_;
  ObservationOutbox* outbox_ = nullptr;
  std::unique_ptr<SceneRecorder> scene_;
  bool scene_started_ = false;
  olympics::match_created_t description_;

  Phase phase_ = Phase::Joining;
  bool start_reported_ = false;
  bool finished_ = false;
  std::vector<Client> clients_;
  std::vector<int> slot_owner_;              // client index or -1
  std::vector<std::vector<float>> current_;  // action applied per slot
  std::vector<std::vector<float>> pending_;  // received for the coming tick
  std::vector<std::uint8_t> has_pending_;
  // Per slot, the newest tick whose action was taken: an older one (late, or replayed) never
  // overrides it.
  std::vector<int> newest_action_tick_;
  std::map<std::string, protocol::LogThrottle> error_logs_;  // by code: a line a second at most
  Clock::time_point created_at_, started_at_, tick_deadline_, next_resend_, next_realtime_tick_;
  std::chrono::system_clock::time_point started_wall_;
  double resend_gap_s_ = 0.03;  // grows while a tick waits, back to resend_interval_s after it
  std::optional<nlohmann::json> forfeit_;
  std::vector<float> replay_actions_;
  olympics::match_result_t result_;
  std::map<std::string, olympics::observation_batch_t> final_batches_;
  std::int64_t finished_at_unix_ = 0;
};

}  // namespace olympics::server
