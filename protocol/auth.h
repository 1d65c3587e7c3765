// Message authentication (docs/security.md). A deployment's secret lives in a file that never
// goes on the wire; from it each side derives one HMAC-SHA256 key per sender role. Every message
// ends with a 56-byte `signature` field: the sender's freshness (its boot id, a sequence number
// and the send time, freshness.h) and then the HMAC, under the sender's role key, of the
// channel's name and the encoded message with the HMAC's 32 bytes zeroed (so the freshness is
// signed too). Signing takes the channel, so a message cannot be moved to another channel; its
// content names the match, client, slots and tick, so a copied client id or a datagram replayed
// into another match or tick is of no use; the freshness makes a replay into the same one
// recognisable (freshness.h).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>

namespace olympics::protocol {

// Who sends on a channel: servers (announcements, descriptions, observations, results, errors),
// or clients (requests, joins, actions, heartbeats; agents, trainers and leagues alike).
enum class Role { Server, Client };
Role sender_of(const std::string& channel);
// The whole trailer (`signature` field): freshness, then the MAC.
inline constexpr int kFreshnessBytes = 24;
inline constexpr int kMacBytes = 32;
inline constexpr int kSignatureBytes = kFreshnessBytes + kMacBytes;

class Authenticator {
 public:
  explicit Authenticator(const std::string& secret);
  ~Authenticator();
  Authenticator(const Authenticator&) = delete;
  Authenticator& operator=(const Authenticator&) = delete;
  Authenticator(Authenticator&& other) noexcept;
  // Reads a secret file; throws std::runtime_error saying what to fix when it is missing, shorter
  // than 16 bytes, or readable by other users.
  static Authenticator from_file(const std::string& path);

  // Signs an encoded message of ours in place: its last 32 bytes get the MAC of the rest (the
  // freshness before them is filled in by the caller, Transport).
  void sign(const std::string& channel, std::uint8_t* bytes, int size) const;
  // Whether an encoded message carries a valid signature for its channel.
  bool verify(const std::string& channel, const std::uint8_t* bytes, int size) const;

 private:
  std::array<unsigned char, kMacBytes> mac(Role role, const std::string& channel,
                                           const std::uint8_t* bytes, int size) const;
  // Per role, an HMAC context keyed once; each message is signed on a copy of it.
  std::array<void*, 2> keyed_{nullptr, nullptr};  // EVP_MAC_CTX*, by Role
};

// The authenticator of a secret file: `path`, or else $OLYMPICS_SECRET_FILE, or else none
// (nullptr: nothing signed or checked).
std::shared_ptr<const Authenticator> load_secret(const std::string& path);

// Writes a new random 32-byte secret (hex) to `path`, readable by its owner only; refuses to
// overwrite a file.
void write_new_secret(const std::string& path);

}  // namespace olympics::protocol
