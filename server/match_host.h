// The server process's core: takes match requests, hosts many matches at once spread over
// worker threads (one world per match), routes each client message to its match, announces
// capacity, and stores every finished match.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

#include "live_scenes.h"
#include "match_runtime.h"
#include "olympics/match_created_t.hpp"
#include "olympics/match_result_t.hpp"
#include "olympics/server_announce_t.hpp"
#include "results_store.h"
#include "transport.h"
#include "write_queue.h"

namespace olympics::server {

struct HostSettings {
  std::string server_id;
  int capacity = 64;           // matches at once
  int workers = 0;             // threads stepping matches; 0 = one per core
  RuntimeSettings sync;        // lockstep matches
  RuntimeSettings realtime;    // 30 Hz clock matches
  std::string replay_dir;      // "" = no replays
  bool lcm_logs = false;       // also write <match>.lcmlog beside the replay
  bool scene_tracks = true;    // also write <match>.scene (for viewers) beside the replay
  LiveScenes* live = nullptr;  // publish every match's scene track to live viewers
  double announce_interval_s = 1.0;
  bool log_finished = true;  // a line on stdout for every finished match (benchmarks: off)
};

class MatchHost {
 public:
  MatchHost(HostSettings settings, protocol::Transport& transport, ResultsStore& store);
  ~MatchHost();

  // Serves until `stop` becomes true.
  void run(const std::atomic<bool>& stop);
  int active_matches() const;
  // CPU time the worker threads have used so far (all of them together).
  double worker_cpu_seconds() const;
  long finished_matches() const { return finished_count_; }

 private:
  struct Inbound {
    std::string channel;
    std::vector<std::uint8_t> bytes;
    bool bundled = false;  // an action batch that came in a client's bundle
  };
  struct Entry {
    std::unique_ptr<MatchRuntime> match;
    std::deque<Inbound> inbox;
  };
  // A request accepted by the receiving thread, for its worker to create.
  struct PendingMatch {
    MatchIdentity identity;  // its id and settings as requested
    std::string request_id;
    const sports::Sport* sport = nullptr;
  };
  struct Worker {
    std::thread thread;
    std::mutex mutex;
    std::condition_variable wake;
    std::unordered_map<std::string, Entry> entries;
    std::deque<PendingMatch> to_create;
    std::vector<std::shared_ptr<MatchRuntime>> retired;  // stored: to destroy on this thread
    ObservationOutbox outbox;                            // the worker thread's own
  };

  void on_request(const std::uint8_t* data, int size);
  // Queues a message for its match's worker (which one; -1: answered here or dropped).
  int route(const std::string& match_id, const std::string& channel, const std::uint8_t* data,
            int size, const std::string& client_id, bool bundled = false);
  void on_action_bundle(const std::uint8_t* data, int size);
  static std::string sender(const std::string& client_id, const std::uint8_t* data, int size);
  void on_announce(const olympics::server_announce_t& announce);
  bool should_take_unaddressed_request();
  void announce();
  void worker_loop(Worker& worker);
  void remove_unfinished_scene_tracks();
  std::unique_ptr<MatchRuntime> create_match(PendingMatch pending);
  void announce_created(const MatchRuntime& match, const std::string& request_id);
  void on_finished(MatchRuntime& match);
  void retire(Worker& worker, std::unique_ptr<MatchRuntime> finished);
  void note_in_progress(const MatchRuntime& match, const MatchIdentity& id);
  void note_players(const MatchRuntime& match);
  // An error, signed. `answered_bytes` > 0: it answers a datagram of that size that did not
  // decode, and is cut to fit it (or not sent): no answer is bigger than its cause.
  void error(const std::string& match_id, const std::string& client_id, const std::string& code,
             const std::string& message, int answered_bytes = 0);
  // The answer to a datagram that failed the signature check (or did not decode): unsigned,
  // naming none of the ids an outsider could have chosen (so it is no oracle, see
  // Transport::publish_unsigned), rate-limited, and never more bytes than the datagram it answers
  // (so it is no amplifier): the message is cut to fit, or nothing goes out.
  void hint(const std::string& code, const std::string& message, int answered_bytes);
  // One log line per error code a second at most (a flood of bad input must not fill the disk).
  void log_error(const std::string& code, const std::string& message);
  std::map<std::string, std::unique_ptr<protocol::LogThrottle>> error_logs_;  // under its mutex
  std::mutex error_logs_mutex_;

  HostSettings settings_;
  protocol::Transport& transport_;
  ResultsStore& store_;
  std::vector<std::unique_ptr<Worker>> workers_;
  std::atomic<bool> stopping_{false};

  mutable std::mutex routes_mutex_;
  std::unordered_map<std::string, int> routes_;  // match id -> worker
  // request id -> created: a resent request gets its match again. Kept while the match plays
  // and for kRequestMemoryS after it ends; a request datagram older than that is stale
  // everywhere (freshness.h), so no replay of an old request can make a second match.
  std::map<std::string, olympics::match_created_t> requests_;
  std::unordered_map<std::string, std::string> request_of_match_;  // match id -> request id
  std::deque<std::pair<std::chrono::steady_clock::time_point, std::string>> finished_requests_;
  void forget_old_requests();  // under routes_mutex_
  struct Finished {
    olympics::match_result_t result;
    std::string obs_channel;
    std::map<std::string, olympics::observation_batch_t> final_batches;  // by client id
    // When each sender was last told the end: a few times a second at most, however often it
    // asks (a client that missed the end resends every 250 ms at most).
    std::map<std::string, std::chrono::steady_clock::time_point> told;
  };
  std::map<std::string, Finished> finished_;  // recent matches' ends, to repeat
  std::deque<std::string> finished_order_;
  std::map<std::string, std::pair<std::chrono::steady_clock::time_point, int>>
      peers_;                                       // id -> seen, free
  std::map<std::string, std::int64_t> peer_boots_;  // id -> newest boot announced
  std::atomic<long> finished_count_{0};
  // Matches requested and not yet finished: what counts against the capacity. A match stops
  // counting as soon as it ends, before its result is stored, so that its players' next
  // requests find the place free.
  std::atomic<int> playing_{0};
  // With LCM's multi-port provider (mpudpm://) a pattern subscription listens on every port, so
  // each match's action channel is subscribed by name while the match and its remembered end
  // last; subscriptions are made and ended on the receiving thread (run()).
  bool exact_action_channels_ = false;
  std::unordered_map<std::string, int> action_subscriptions_;  // match id -> handle
  std::vector<std::string> to_unsubscribe_;                    // under routes_mutex_
  void subscribe_actions(const std::string& match_id);
  const std::int64_t boot_us_;  // when this process started: announced
  const std::string boot_tag_;  // the same in ms, base 36: in match ids
  long next_match_number_ = 1;
  int next_worker_ = 0;
  // The results store's and replays' writes, in order, off the workers. Last: its destructor
  // runs what is left, which needs everything above.
  WriteQueue writes_;
};

}  // namespace olympics::server
