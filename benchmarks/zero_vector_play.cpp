#include "zero_vector_play.h"

#include <span>

namespace olympics::bench {

ZeroVectorPlay::ZeroVectorPlay(client::VectorClient& client, int async_batch)
    : client_(client), async_batch_(async_batch) {
  const std::vector<int> first = client_.reset().envs;
  zero_.assign(first.size() * client_.num_agents() * client_.action_size(), 0.0f);
  if (async_batch_ > 0) client_.send(first, zero_);
}

int ZeroVectorPlay::round() {
  if (async_batch_ == 0) {
    client_.step(zero_);
    return client_.num_envs();
  }
  const std::vector<int> envs = client_.recv(async_batch_).envs;
  client_.send(envs, std::span<const float>(zero_).first(envs.size() * client_.num_agents() *
                                                         client_.action_size()));
  return static_cast<int>(envs.size());
}

}  // namespace olympics::bench
