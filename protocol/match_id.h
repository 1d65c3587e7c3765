// Match ids: "<server id>-<boot>-<n>", the boot being the server process's start in Unix
// milliseconds, base 36. Server ids hold no '-' (server_config.cpp), so an id splits one way;
// the boot in it tells a client which boot of its server hosts the match (an announcement of an
// earlier boot is a replay, of a later one a restart).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace olympics::protocol {

std::string boot_tag(std::int64_t boot_us);
std::string make_match_id(const std::string& server_id, const std::string& boot_tag, long n);
// The boot (Unix ms) a match id names; nullopt for an id of another form.
std::optional<std::int64_t> match_boot_ms(const std::string& match_id);

}  // namespace olympics::protocol
