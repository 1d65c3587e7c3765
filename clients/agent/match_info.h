// What a policy is told about its match before it plays: the sport and mode, the tick length,
// and where each named block of the observation and each field inside it lies. The server sends
// them (match_created_t); a policy looks them up by name (observation_layout.h, the client
// library's) instead of copying offsets by hand.
#pragma once

#include <string>

#include "observation_layout.h"

namespace olympics::client {

struct MatchInfo {
  std::string sport, mode;
  double control_dt = 0;  // seconds per tick (1 / match_created_t.control_hz)
  ObservationLayout observation;
  int action_size = 0;
};

}  // namespace olympics::client
