// A vector client playing zero actions, as the benches drive it: sync (step() of every match)
// or async (EnvPool's send/recv: each recv takes the first `async_batch` matches whose
// observation is in and sends their actions at once, so the server always has work).
#pragma once

#include <vector>

#include "vector_client.h"

namespace olympics::bench {

class ZeroVectorPlay {
 public:
  // `client` freshly made; async_batch 0 = sync. Starts every match (reset) and, async, sends
  // every match's first actions.
  ZeroVectorPlay(client::VectorClient& client, int async_batch);
  // One step (sync) or one recv and send (async); the matches stepped.
  int round();

 private:
  client::VectorClient& client_;
  int async_batch_;
  std::vector<float> zero_;  // every match's actions
};

}  // namespace olympics::bench
