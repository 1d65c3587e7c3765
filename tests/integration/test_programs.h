// Where the integration tests find the programs, and private LCM ports per test.
#pragma once

#include <unistd.h>

#include <string>

#include "process.h"

namespace olympics::testing {

using olympics::Process;
using olympics::temp_dir;

// A fresh LCM URL (own port) per call, so tests never hear each other.
inline std::string unique_lcm_url() {
  static int counter = 0;
  int port = 20000 + (getpid() * 7 + counter++ * 101) % 30000;
  return "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0&recv_buf_size=4194304";
}

// build/bin/<name>
inline std::string program(const std::string& name) {
  return std::string(OLYMPICS_BIN_DIR) + "/" + name;
}

}  // namespace olympics::testing
