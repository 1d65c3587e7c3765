// Scene tracks of the matches being played, for live viewers (olympics-server serve
// --view-port). The stepping threads publish each tick's records; viewer threads poll for them
// at their own pace. A stepping thread never waits for a viewer nor wakes one: it takes one
// short lock to append, and a viewer that falls behind skips to the newest frame (every frame
// is a whole pose).
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace olympics::server {

class LiveScene {
 public:
  explicit LiveScene(nlohmann::json summary) : summary_(std::move(summary)) {}
  void publish_header(std::string records);
  // One tick's records (a frame, perhaps its events).
  void publish_tick(int tick, std::string records);
  void end(std::string records);

  struct Batch {
    std::vector<std::string> records;
    std::uint64_t next = 0;  // pass back to get what follows
    bool ended = false;
  };
  // What follows `after` (0: a new viewer, who gets the header, the last score and the newest
  // tick); waits up to `timeout` when there is nothing new yet.
  Batch wait(std::uint64_t after, std::chrono::milliseconds timeout);
  nlohmann::json summary() const;
  bool ended() const;
  std::chrono::steady_clock::time_point ended_at() const;

  static constexpr size_t kKeptTicks = 90;  // 3 s at 30 Hz for a viewer that lags
  static constexpr std::chrono::milliseconds kPollInterval{15};

 private:
  mutable std::mutex mutex_;
  nlohmann::json summary_;
  std::string header_, last_events_, result_;
  std::deque<std::string> recent_;  // ticks first_seq_ .. next_seq_ - 1
  std::uint64_t first_seq_ = 1, next_seq_ = 1;
  int tick_ = 0;
  bool ended_ = false;
  std::chrono::steady_clock::time_point ended_at_;
};

// Every live match of this server; ended ones are listed for a minute.
class LiveScenes {
 public:
  std::shared_ptr<LiveScene> add(const std::string& match_id, nlohmann::json summary);
  std::shared_ptr<LiveScene> find(const std::string& match_id) const;
  nlohmann::json list() const;

 private:
  void prune() const;
  mutable std::mutex mutex_;
  mutable std::map<std::string, std::shared_ptr<LiveScene>> scenes_;
};

}  // namespace olympics::server
