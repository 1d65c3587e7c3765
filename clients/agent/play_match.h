// Playing a joined match with one named policy per slot, to its end: what olympics-agent does for
// every match, and what in-process players (olympics-bench soak) do.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "match_client.h"
#include "match_info.h"
#include "olympics/match_created_t.hpp"

namespace olympics::client {

// What the policies are told of the match they are about to play; throws std::invalid_argument
// for a description without a control rate (a server older than protocol 3).
MatchInfo match_info(const olympics::match_created_t& match);

struct PlayOptions {
  std::string policy = "zero";    // make_policy's names
  std::uint64_t policy_seed = 1;  // slot i plays with seed policy_seed + i
  int think_ms = 0;               // sleep this long before each action (a slow policy)
  double timeout_s = 60;          // for each observation and the result
  // Called with every observation batch as it arrives, the last one included.
  std::function<void(const Observation&)> on_observation;
};

// Plays the match `client` has joined, for the slots it joined, until every slot is done;
// returns the result. Scripted players keep state (their gait, the ball they chase), so each
// slot has a policy of its own, started with the match's description.
const olympics::match_result_t& play_joined_match(MatchClient& client, const PlayOptions& options);

}  // namespace olympics::client
