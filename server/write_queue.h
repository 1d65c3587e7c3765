// One thread that does the server's slow writes (the results store, replay files) in the order
// they were posted, so that stepping threads hand them off and step on. With many workers the
// store's one connection would otherwise make each worker wait, at every match start and end,
// for the others' writes.
#pragma once

#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

namespace olympics::server {

class WriteQueue {
 public:
  WriteQueue();
  // Runs what was posted, then stops.
  ~WriteQueue();
  WriteQueue(const WriteQueue&) = delete;
  WriteQueue& operator=(const WriteQueue&) = delete;

  void post(std::function<void()> job);

 private:
  void run();

  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::function<void()>> jobs_;
  bool stopping_ = false;
  std::thread thread_;  // last: it starts once the rest is ready
};

}  // namespace olympics::server
