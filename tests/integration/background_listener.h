// A test's own LCM transport whose messages are handled on a thread of its own, from listen()
// until it is destroyed: make the subscriptions (on transport()) before listen().
#pragma once

#include <atomic>
#include <string>
#include <thread>

#include "transport.h"

namespace olympics::testing {

class BackgroundListener {
 public:
  explicit BackgroundListener(const std::string& url)
      : transport_(protocol::TransportOptions(url)) {}
  ~BackgroundListener() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  protocol::Transport& transport() { return transport_; }
  void listen() {
    thread_ = std::thread([this] {
      while (!stop_) transport_.handle(20);
    });
  }

 private:
  protocol::Transport transport_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace olympics::testing
