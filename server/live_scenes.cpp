#include "live_scenes.h"

#include <cstring>
#include <thread>

namespace olympics::server {

void LiveScene::publish_header(std::string records) {
  std::lock_guard lock(mutex_);
  header_ = std::move(records);
}

void LiveScene::publish_tick(int tick, std::string records) {
  // Keep the newest events record for viewers who join later (it carries the score); found
  // before taking the lock that viewers wait on.
  std::string events;
  for (size_t at = 0; at + 5 <= records.size();) {
    std::uint32_t size;
    std::memcpy(&size, records.data() + at + 1, 4);
    if (records[at] == 'E') events = records.substr(at, 5 + size);
    at += 5 + size;
  }
  {
    std::lock_guard lock(mutex_);
    if (!events.empty()) last_events_ = std::move(events);
    recent_.push_back(std::move(records));
    ++next_seq_;
    tick_ = tick;
    while (recent_.size() > kKeptTicks) recent_.pop_front(), ++first_seq_;
  }
}

void LiveScene::end(std::string records) {
  {
    std::lock_guard lock(mutex_);
    result_ = std::move(records);
    ended_ = true;
    ended_at_ = std::chrono::steady_clock::now();
  }
}

LiveScene::Batch LiveScene::wait(std::uint64_t after, std::chrono::milliseconds timeout) {
  // Viewers poll (a browser draws at most 60 frames a second): the stepping thread that
  // publishes never wakes anyone, so a viewer costs it nothing but a short lock.
  const auto give_up = std::chrono::steady_clock::now() + timeout;
  std::unique_lock lock(mutex_);
  auto ready = [&] {
    return after == 0 ? !header_.empty() || ended_ : next_seq_ > after || ended_;
  };
  while (!ready() && std::chrono::steady_clock::now() < give_up) {
    lock.unlock();
    std::this_thread::sleep_for(kPollInterval);
    lock.lock();
  }
  Batch b;
  if (after == 0) {
    if (header_.empty()) return b;
    b.records.push_back(header_);
    if (!last_events_.empty()) b.records.push_back(last_events_);
    if (!recent_.empty()) b.records.push_back(recent_.back());
    b.next = next_seq_;
  } else {
    std::uint64_t from = std::max(after, first_seq_);
    if (from < next_seq_ && next_seq_ - from > kKeptTicks / 2) from = next_seq_ - 1;  // lagging
    for (std::uint64_t s = from; s < next_seq_; ++s) b.records.push_back(recent_[s - first_seq_]);
    b.next = next_seq_;
  }
  if (ended_ && b.next == next_seq_) {
    b.records.push_back(result_);
    b.ended = true;
  }
  return b;
}

nlohmann::json LiveScene::summary() const {
  std::lock_guard lock(mutex_);
  nlohmann::json s = summary_;
  s["tick"] = tick_;
  s["ended"] = ended_;
  return s;
}

bool LiveScene::ended() const {
  std::lock_guard lock(mutex_);
  return ended_;
}

std::chrono::steady_clock::time_point LiveScene::ended_at() const {
  std::lock_guard lock(mutex_);
  return ended_at_;
}

std::shared_ptr<LiveScene> LiveScenes::add(const std::string& match_id, nlohmann::json summary) {
  auto scene = std::make_shared<LiveScene>(std::move(summary));
  std::lock_guard lock(mutex_);
  prune();
  scenes_[match_id] = scene;
  return scene;
}

std::shared_ptr<LiveScene> LiveScenes::find(const std::string& match_id) const {
  std::lock_guard lock(mutex_);
  auto it = scenes_.find(match_id);
  return it == scenes_.end() ? nullptr : it->second;
}

nlohmann::json LiveScenes::list() const {
  std::lock_guard lock(mutex_);
  prune();
  nlohmann::json out = nlohmann::json::array();
  for (const auto& [id, scene] : scenes_) out.push_back(scene->summary());
  return out;
}

void LiveScenes::prune() const {
  const auto cutoff = std::chrono::steady_clock::now() - std::chrono::seconds(60);
  for (auto it = scenes_.begin(); it != scenes_.end();)
    it = it->second->ended() && it->second->ended_at() < cutoff ? scenes_.erase(it) : std::next(it);
}

}  // namespace olympics::server
