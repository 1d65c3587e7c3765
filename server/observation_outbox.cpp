#include "observation_outbox.h"

#include "channels.h"

namespace olympics::server {

void ObservationOutbox::add(const std::string& client_id, const std::string& match_id,
                            std::span<const std::uint8_t> batch) {
  by_client_.try_emplace(client_id, client_id).first->second.add(match_id, batch);
}

void ObservationOutbox::flush(protocol::Transport& transport) {
  for (auto& [client_id, writer] : by_client_) {
    const std::string channel = protocol::obs_bundle_channel(client_id);
    for (const auto& bundle : writer.take())
      transport.publish_raw(channel, bundle.data(), static_cast<int>(bundle.size()));
  }
  by_client_.clear();
}

}  // namespace olympics::server
