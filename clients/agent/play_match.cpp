#include "play_match.h"

#include <chrono>
#include <memory>
#include <stdexcept>
#include <thread>

#include "policies.h"

namespace olympics::client {

MatchInfo match_info(const olympics::match_created_t& m) {
  if (m.control_hz <= 0)
    throw std::invalid_argument("the server sent no control rate; upgrade it to protocol 3");
  return {m.sport, m.mode, 1.0 / m.control_hz, ObservationLayout::from_message(m), m.action_size};
}

const olympics::match_result_t& play_joined_match(MatchClient& client, const PlayOptions& o) {
  const MatchInfo info = match_info(client.match());
  std::vector<std::unique_ptr<Policy>> policies;
  std::vector<std::vector<float>> actions;
  while (auto obs = client.next(o.timeout_s)) {
    if (o.on_observation) o.on_observation(*obs);
    if (obs->all_done()) break;
    while (policies.size() < obs->slots.size()) {
      policies.push_back(make_policy(o.policy, o.policy_seed + policies.size()));
      policies.back()->start(info);
      actions.emplace_back(info.action_size);
    }
    for (size_t i = 0; i < obs->slots.size(); ++i) policies[i]->act(obs->obs[i], actions[i]);
    if (o.think_ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(o.think_ms));
    client.act(obs->tick, actions);
  }
  return client.wait_result(o.timeout_s);
}

}  // namespace olympics::client
