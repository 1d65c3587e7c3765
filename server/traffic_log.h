// An LCM event log of one match's traffic, readable by lcm-logplayer and lcm-logger tools.
#pragma once

#include <chrono>
#include <cstdint>
#include <lcm/lcm-cpp.hpp>
#include <memory>
#include <string>

namespace olympics::server {

class TrafficLog {
 public:
  // Throws std::runtime_error when the file cannot be created.
  explicit TrafficLog(const std::string& path);
  void write(const std::string& channel, const std::uint8_t* data, int size);
  // What was written is in the file (for readers while the log is still open).
  void flush();
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::unique_ptr<lcm::LogFile> file_;
  std::int64_t next_event_ = 0;
};

}  // namespace olympics::server
