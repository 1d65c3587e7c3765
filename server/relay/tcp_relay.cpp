#include "tcp_relay.h"

#include <arpa/inet.h>
#include <lcm/lcm.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/random.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "auth.h"
#include "channels.h"

namespace olympics::relay {
namespace {

constexpr int kNonceBytes = 32;
constexpr std::uint32_t kMaxMessageBytes = 16u << 20;
// Each side proves it holds the secret over the other's fresh challenge, under its own role's
// label, so a challenge reflected back to its sender proves nothing.
constexpr const char* kCellProof = "olympics relay cell";
constexpr const char* kLearnerProof = "olympics relay learner";
constexpr const char* kProofChannel = "OLY_RELAY_HANDSHAKE";

// A TCP socket closed when it goes out of scope.
struct Socket {
  int fd = -1;
  explicit Socket(int f) : fd(f) {}
  ~Socket() {
    if (fd >= 0) close(fd);
  }
  Socket(const Socket&) = delete;
  Socket& operator=(const Socket&) = delete;
};

void write_all(int fd, const void* data, size_t size) {
  const auto* p = static_cast<const std::uint8_t*>(data);
  while (size > 0) {
    const ssize_t n = send(fd, p, size, MSG_NOSIGNAL);
    if (n <= 0) throw std::runtime_error(std::string("the peer is gone: ") + std::strerror(errno));
    p += n, size -= static_cast<size_t>(n);
  }
}

void read_all(int fd, void* data, size_t size) {
  auto* p = static_cast<std::uint8_t*>(data);
  while (size > 0) {
    const ssize_t n = recv(fd, p, size, 0);
    if (n == 0) throw std::runtime_error("the peer closed the connection");
    if (n < 0)
      throw std::runtime_error(std::string("reading from the peer: ") + std::strerror(errno));
    p += n, size -= static_cast<size_t>(n);
  }
}

using Nonce = std::array<std::uint8_t, kNonceBytes>;

Nonce fresh_nonce() {
  Nonce n;
  if (getrandom(n.data(), n.size(), 0) != static_cast<ssize_t>(n.size()))
    throw std::runtime_error("no randomness for the relay's challenge");
  return n;
}

// The bytes a proof signs: the role's label and the challenge, with room for the signature.
std::vector<std::uint8_t> proof_bytes(const char* label, const Nonce& challenge) {
  std::vector<std::uint8_t> bytes(label, label + std::strlen(label));
  bytes.insert(bytes.end(), challenge.begin(), challenge.end());
  bytes.resize(bytes.size() + protocol::kSignatureBytes);
  return bytes;
}

// Both sides send a challenge, answer the other's, and check the answer to their own.
void handshake(int fd, const protocol::Authenticator& auth, bool cell) {
  const Nonce mine = fresh_nonce();
  Nonce theirs;
  write_all(fd, mine.data(), mine.size());
  read_all(fd, theirs.data(), theirs.size());
  auto answer = proof_bytes(cell ? kCellProof : kLearnerProof, theirs);
  auth.sign(kProofChannel, answer.data(), static_cast<int>(answer.size()));
  write_all(fd, answer.data() + answer.size() - protocol::kSignatureBytes,
            protocol::kSignatureBytes);
  auto expected = proof_bytes(cell ? kLearnerProof : kCellProof, mine);
  read_all(fd, expected.data() + expected.size() - protocol::kSignatureBytes,
           protocol::kSignatureBytes);
  if (!auth.verify(kProofChannel, expected.data(), static_cast<int>(expected.size())))
    throw std::runtime_error(
        "the peer does not hold this deployment's secret (its answer to the challenge is wrong); "
        "give both relays the same --secret");
}

std::size_t message_hash(std::string_view channel, const void* data, std::size_t size) {
  return std::hash<std::string_view>{}(channel)*31 ^
         std::hash<std::string_view>{}(std::string_view(static_cast<const char*>(data), size));
}

// Relays between this host's LCM and the peer until the connection ends or `stop` is set.
class Link {
 public:
  Link(const RelaySettings& settings, int fd, RelayCounts& counts)
      : fd_(fd),
        counts_(counts),
        lcm_(lcm_create(settings.lcm_url.empty() ? protocol::kDefaultLcmUrl
                                                 : settings.lcm_url.c_str())) {
    if (!lcm_) throw std::runtime_error("cannot open LCM on " + settings.lcm_url);
    lcm_subscribe(lcm_, ".*", &Link::heard, this);
  }
  ~Link() { lcm_destroy(lcm_); }

  void run(const std::atomic<bool>* stop) {
    pollfd fds[2] = {{lcm_get_fileno(lcm_), POLLIN, 0}, {fd_, POLLIN, 0}};
    while (!(stop && *stop)) {
      if (poll(fds, 2, 100) < 0 && errno != EINTR) throw std::runtime_error("poll failed");
      if (fds[0].revents & POLLIN) lcm_handle(lcm_);
      if (!failed_.empty()) throw std::runtime_error(failed_);
      if (fds[1].revents & (POLLIN | POLLHUP | POLLERR)) from_peer();
    }
  }

 private:
  // A message heard on this host: to the peer, unless it is one this relay just published.
  static void heard(const lcm_recv_buf_t* rbuf, const char* channel, void* self_ptr) {
    auto* self = static_cast<Link*>(self_ptr);
    const auto echo = self->published_.find(message_hash(channel, rbuf->data, rbuf->data_size));
    if (echo != self->published_.end()) {
      self->published_.erase(echo);
      return;
    }
    const auto length = static_cast<std::uint8_t>(std::min<size_t>(std::strlen(channel), 255));
    const std::uint32_t size = htonl(rbuf->data_size);
    std::vector<std::uint8_t> frame;
    frame.reserve(1 + length + 4 + rbuf->data_size);
    frame.push_back(length);
    frame.insert(frame.end(), channel, channel + length);
    frame.insert(frame.end(), reinterpret_cast<const std::uint8_t*>(&size),
                 reinterpret_cast<const std::uint8_t*>(&size) + 4);
    const auto* data = static_cast<const std::uint8_t*>(rbuf->data);
    frame.insert(frame.end(), data, data + rbuf->data_size);
    try {  // LCM's C dispatch must not see an exception: run() rethrows it
      write_all(self->fd_, frame.data(), frame.size());
      ++self->counts_.sent;
    } catch (const std::runtime_error& e) {
      self->failed_ = e.what();
    }
  }

  // One message from the peer: published here (and remembered, so that hearing it is no echo).
  void from_peer() {
    std::uint8_t length = 0;
    read_all(fd_, &length, 1);
    std::string channel(length, '\0');
    read_all(fd_, channel.data(), length);
    std::uint32_t size = 0;
    read_all(fd_, &size, 4);
    size = ntohl(size);
    if (size > kMaxMessageBytes)
      throw std::runtime_error("the peer sent a message of " + std::to_string(size) + " bytes");
    std::vector<std::uint8_t> data(size);
    read_all(fd_, data.data(), size);
    if (published_.size() > 100000) published_.clear();  // echoes never heard (a full buffer)
    published_.insert(message_hash(channel, data.data(), data.size()));
    lcm_publish(lcm_, channel.c_str(), data.data(), size);
    ++counts_.received;
  }

  int fd_;
  RelayCounts& counts_;
  lcm_t* lcm_;
  std::unordered_multiset<std::size_t> published_;
  std::string failed_;  // why sending to the peer failed, inside LCM's dispatch
};

void no_delay(int fd) {
  int one = 1;
  setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
}

void need_secret(const RelaySettings& settings) {
  if (!settings.auth)
    throw std::invalid_argument(
        "the relay needs the deployment's secret (--secret or OLYMPICS_SECRET_FILE): it admits "
        "only a peer that holds it");
}

}  // namespace

void serve(const RelaySettings& settings, const std::string& bind_address, int port,
           RelayCounts& counts) {
  need_secret(settings);
  Socket listener(socket(AF_INET, SOCK_STREAM, 0));
  int one = 1;
  setsockopt(listener.fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  if (inet_pton(AF_INET, bind_address.c_str(), &address.sin_addr) != 1)
    throw std::invalid_argument("--bind " + bind_address + " is not an IPv4 address");
  if (bind(listener.fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
      listen(listener.fd, 4) != 0)
    throw std::runtime_error("cannot listen on " + bind_address + ":" + std::to_string(port) +
                             ": " + std::strerror(errno));
  std::fprintf(stderr, "relay: listening on %s:%d\n", bind_address.c_str(), port);
  for (;;) {
    sockaddr_in peer{};
    socklen_t size = sizeof peer;
    Socket connection(accept(listener.fd, reinterpret_cast<sockaddr*>(&peer), &size));
    if (connection.fd < 0) continue;
    char who[INET_ADDRSTRLEN] = "?";
    inet_ntop(AF_INET, &peer.sin_addr, who, sizeof who);
    try {
      no_delay(connection.fd);
      handshake(connection.fd, *settings.auth, true);
      std::fprintf(stderr, "relay: learner %s admitted\n", who);
      Link(settings, connection.fd, counts).run(nullptr);
    } catch (const std::runtime_error& e) {
      std::fprintf(stderr, "relay: learner %s: %s\n", who, e.what());
    }
  }
}

void connect_and_relay(const RelaySettings& settings, const std::string& host, int port,
                       RelayCounts& counts, const std::atomic<bool>& stop) {
  need_secret(settings);
  addrinfo hints{}, *found = nullptr;
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_STREAM;
  if (getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found) != 0 || !found)
    throw std::runtime_error("cannot resolve " + host);
  Socket connection(socket(AF_INET, SOCK_STREAM, 0));
  const int rc = connect(connection.fd, found->ai_addr, found->ai_addrlen);
  freeaddrinfo(found);
  if (rc != 0)
    throw std::runtime_error("cannot connect to the cell's relay at " + host + ":" +
                             std::to_string(port) + ": " + std::strerror(errno));
  no_delay(connection.fd);
  handshake(connection.fd, *settings.auth, false);
  std::fprintf(stderr, "relay: connected to %s:%d\n", host.c_str(), port);
  Link(settings, connection.fd, counts).run(&stop);
}

}  // namespace olympics::relay
