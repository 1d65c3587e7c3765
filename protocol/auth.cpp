#include "auth.h"

#include <fcntl.h>
#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>
#include <openssl/params.h>
#include <openssl/rand.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "channels.h"

namespace olympics::protocol {
namespace {

std::array<unsigned char, kMacBytes> hmac(const unsigned char* key, int key_size,
                                          const unsigned char* data, size_t size) {
  std::array<unsigned char, kMacBytes> out{};
  unsigned int length = 0;
  if (!HMAC(EVP_sha256(), key, key_size, data, size, out.data(), &length) || length != kMacBytes)
    throw std::runtime_error("HMAC-SHA256 failed (OpenSSL)");
  return out;
}

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

}  // namespace

Role sender_of(const std::string& channel) {
  for (const char* server : {kAnnounce, kCreated, kJoinReply, kStart, kResult, kError})
    if (channel == server) return Role::Server;
  return starts_with(channel, kObsPrefix) || starts_with(channel, kObsBundlePrefix) ? Role::Server
                                                                                    : Role::Client;
}

Authenticator::Authenticator(const std::string& secret) {
  EVP_MAC* mac = EVP_MAC_fetch(nullptr, "HMAC", nullptr);
  if (!mac) throw std::runtime_error("OpenSSL has no HMAC");
  char digest[] = "SHA256";
  const OSSL_PARAM params[] = {OSSL_PARAM_construct_utf8_string("digest", digest, 0),
                               OSSL_PARAM_construct_end()};
  for (Role role : {Role::Server, Role::Client}) {
    const std::string purpose =
        std::string("olympics-v1 ") + (role == Role::Server ? "server" : "client");
    const auto key =
        hmac(reinterpret_cast<const unsigned char*>(secret.data()), static_cast<int>(secret.size()),
             reinterpret_cast<const unsigned char*>(purpose.data()), purpose.size());
    EVP_MAC_CTX* ctx = EVP_MAC_CTX_new(mac);
    if (!ctx || !EVP_MAC_init(ctx, key.data(), key.size(), params))
      throw std::runtime_error("HMAC-SHA256 keying failed (OpenSSL)");
    keyed_[static_cast<int>(role)] = ctx;
  }
  EVP_MAC_free(mac);
}

Authenticator::~Authenticator() {
  for (void* ctx : keyed_) EVP_MAC_CTX_free(static_cast<EVP_MAC_CTX*>(ctx));
}

Authenticator::Authenticator(Authenticator&& other) noexcept : keyed_(other.keyed_) {
  other.keyed_ = {nullptr, nullptr};
}

Authenticator Authenticator::from_file(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0)
    throw std::runtime_error("secret file " + path + " cannot be read: " + std::strerror(errno) +
                             " (make one with `olympics-server secret " + path + "`)");
  // Reading a FIFO or a device blocks or never ends: refuse before opening it.
  if (!S_ISREG(st.st_mode))
    throw std::runtime_error("secret file " + path +
                             " is not a regular file (a FIFO, device or folder); give the file "
                             "`olympics-server secret FILE` made");
  if (st.st_mode & (S_IRWXG | S_IRWXO))
    throw std::runtime_error("secret file " + path + " is open to other users; `chmod 600 " + path +
                             "` first");
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  std::string secret = text.str();
  while (!secret.empty() && std::isspace(static_cast<unsigned char>(secret.back())))
    secret.pop_back();
  if (secret.size() < 16)
    throw std::runtime_error("secret file " + path + " holds " + std::to_string(secret.size()) +
                             " bytes; a secret needs at least 16 (make one with `olympics-server "
                             "secret FILE`)");
  return Authenticator(secret);
}

std::array<unsigned char, kMacBytes> Authenticator::mac(Role role, const std::string& channel,
                                                        const std::uint8_t* bytes, int size) const {
  // channel, a NUL, then the message (its freshness included) with the MAC's bytes zeroed
  static const unsigned char zeros[kMacBytes + 1] = {};
  EVP_MAC_CTX* ctx = EVP_MAC_CTX_dup(static_cast<EVP_MAC_CTX*>(keyed_[static_cast<int>(role)]));
  std::array<unsigned char, kMacBytes> out{};
  size_t length = 0;
  const bool ok =
      ctx &&
      EVP_MAC_update(ctx, reinterpret_cast<const unsigned char*>(channel.data()), channel.size()) &&
      EVP_MAC_update(ctx, zeros, 1) &&
      EVP_MAC_update(ctx, bytes, static_cast<size_t>(size - kMacBytes)) &&
      EVP_MAC_update(ctx, zeros, kMacBytes) &&
      EVP_MAC_final(ctx, out.data(), &length, out.size()) && length == kMacBytes;
  EVP_MAC_CTX_free(ctx);
  if (!ok) throw std::runtime_error("HMAC-SHA256 failed (OpenSSL)");
  return out;
}

void Authenticator::sign(const std::string& channel, std::uint8_t* bytes, int size) const {
  if (size < kSignatureBytes + 8) return;  // not one of our messages
  const auto m = mac(sender_of(channel), channel, bytes, size);
  std::memcpy(bytes + size - kMacBytes, m.data(), kMacBytes);
}

bool Authenticator::verify(const std::string& channel, const std::uint8_t* bytes, int size) const {
  if (!bytes || size < kSignatureBytes + 8) return false;
  const auto m = mac(sender_of(channel), channel, bytes, size);
  return CRYPTO_memcmp(m.data(), bytes + size - kMacBytes, kMacBytes) == 0;
}

std::shared_ptr<const Authenticator> load_secret(const std::string& path) {
  std::string file = path;
  if (file.empty())
    if (const char* env = std::getenv("OLYMPICS_SECRET_FILE")) file = env;
  if (file.empty()) return nullptr;
  return std::make_shared<const Authenticator>(Authenticator::from_file(file));
}

void write_new_secret(const std::string& path) {
  unsigned char raw[32];
  if (RAND_bytes(raw, sizeof raw) != 1) throw std::runtime_error("no random bytes (OpenSSL)");
  char hex[2 * sizeof raw + 2];
  for (size_t i = 0; i < sizeof raw; ++i) std::snprintf(hex + 2 * i, 3, "%02x", raw[i]);
  hex[2 * sizeof raw] = '\n';
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (fd < 0)
    throw std::runtime_error("cannot create " + path + ": " + std::strerror(errno) +
                             " (an existing secret is never overwritten)");
  const bool ok = write(fd, hex, 2 * sizeof raw + 1) == static_cast<ssize_t>(2 * sizeof raw + 1);
  close(fd);
  if (!ok) throw std::runtime_error("could not write " + path);
}

}  // namespace olympics::protocol
