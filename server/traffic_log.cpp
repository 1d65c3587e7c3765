#include "traffic_log.h"

#include <cstdio>
#include <stdexcept>

namespace olympics::server {

TrafficLog::TrafficLog(const std::string& path)
    : path_(path), file_(std::make_unique<lcm::LogFile>(path, "w")) {
  if (!file_->good()) throw std::runtime_error("cannot create LCM log " + path);
}

void TrafficLog::write(const std::string& channel, const std::uint8_t* data, int size) {
  lcm::LogEvent event;
  event.eventnum = next_event_++;
  event.timestamp = std::chrono::duration_cast<std::chrono::microseconds>(
                        std::chrono::system_clock::now().time_since_epoch())
                        .count();
  event.channel = channel;
  event.datalen = size;
  event.data = const_cast<std::uint8_t*>(data);
  file_->writeEvent(&event);
}

void TrafficLog::flush() { std::fflush(file_->getFilePtr()); }

}  // namespace olympics::server
