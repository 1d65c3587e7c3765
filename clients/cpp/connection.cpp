#include "connection.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>

#include "bundle.h"
#include "channels.h"
#include "observation_layout.h"
#include "olympics/join_reply_t.hpp"
#include "olympics/join_t.hpp"
#include "olympics/league_assignment_t.hpp"
#include "olympics/server_announce_t.hpp"
#include "version.h"

namespace olympics::client {
namespace {

std::string random_id() {
  std::random_device rd;
  std::mt19937_64 rng((static_cast<std::uint64_t>(rd()) << 32) ^ rd() ^
                      static_cast<std::uint64_t>(getpid()));
  char buf[24];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(rng()));
  return buf;
}

// A match description a policy can rely on: the blocks add up to the observation, each block's
// fields to the block, sizes are sane.
bool described_consistently(const olympics::match_created_t& m) {
  long blocks = 0;
  for (int size : m.obs_block_sizes) blocks += size;
  if (!(m.obs_size > 0 && m.obs_size <= 1'000'000 && blocks == m.obs_size && m.action_size > 0 &&
        m.action_size <= 100'000 && m.control_hz > 0))
    return false;
  try {
    ObservationLayout::from_message(m);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

template <typename T>
void push_bounded(std::deque<T>& queue, T item, size_t capacity) {
  if (queue.size() >= capacity) queue.pop_front();
  queue.push_back(std::move(item));
}

}  // namespace

std::chrono::steady_clock::duration seconds(double s) {
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(s));
}

Connection::Connection(const ClientOptions& options)
    : options_(options),
      client_id_(options.agent_name + "-" + random_id()),
      transport_({options.lcm_url, options.drop_rate, options.drop_seed,
                  protocol::load_secret(options.secret_file)}),
      exact_observation_channels_(transport_.url().rfind("mpudpm://", 0) == 0) {
  if (!transport_.authenticating() && protocol::multicast_ttl(transport_.url()) > 0)
    std::fprintf(stderr,
                 "olympics client: NO SECRET on %s, which reaches the LAN (ttl > 0): messages are "
                 "neither signed nor checked, anyone there can act for this client's slots "
                 "(docs/security.md: --secret)\n",
                 transport_.url().c_str());
  transport_.subscribe_to<olympics::match_created_t>(
      protocol::kCreated, [this](const std::string&, const olympics::match_created_t& m) {
        if (pending_requests_.count(m.request_id)) created_[m.request_id] = m, answered_ = true;
      });
  transport_.subscribe_to<olympics::join_reply_t>(
      protocol::kJoinReply, [this](const std::string&, const olympics::join_reply_t& m) {
        if (m.client_id != client_id_) return;
        if (m.accepted && !described_consistently(m.match)) return transport_.count_malformed();
        join_replies_[m.match_id] = {m.accepted != 0, m.reason, m.match};
        answered_ = true;
      });
  transport_.subscribe_to<olympics::error_t>(
      protocol::kError, [this](const std::string&, const olympics::error_t& m) { on_error(m); });
  transport_.subscribe_to<olympics::league_assignment_t>(
      protocol::kLeague, [this](const std::string&, const olympics::league_assignment_t& a) {
        if (assigned_matches_.count(a.match_id)) return;
        for (const auto& queued : assignments_)
          if (queued.match_id == a.match_id) return;
        push_bounded(assignments_, {a.league, a.learner, a.match_id, a.opponent, a.game, a.slots},
                     kMaxQueued);
      });
  transport_.subscribe_to<olympics::match_result_t>(
      protocol::kResult, [this](const std::string&, const olympics::match_result_t& m) {
        if (auto it = watched_.find(m.match_id); it != watched_.end()) it->second = m;
      });
  transport_.subscribe_to<olympics::bundle_t>(
      protocol::obs_bundle_channel(client_id_),
      [this](const std::string&, const olympics::bundle_t& bundle) {
        if (bundle.client_id != client_id_) return;
        const bool whole = protocol::for_each_part(
            bundle, [&](const std::string& match_id, const std::uint8_t* data, int size) {
              on_observation_message(match_id, data, size);
            });
        if (!whole) transport_.count_malformed();
      });
  // Every joined match's own observation channel: one pattern, matched once per message, where
  // a subscription per match would have LCM match every message against each of them (a
  // vector client joins hundreds). LCM's multi-port provider listens on every port for a
  // pattern, so there each match's channel is subscribed by name instead.
  if (!exact_observation_channels_)
    transport_.subscribe(std::string(protocol::kObsPrefix) + ".*",
                         [this](const std::string& channel, const std::uint8_t* data, int size) {
                           static const size_t prefix = std::strlen(protocol::kObsPrefix);
                           on_observation_message(channel.substr(prefix), data, size);
                         });
  transport_.subscribe_to<olympics::server_announce_t>(
      protocol::kAnnounce, [this](const std::string&, const olympics::server_announce_t& a) {
        if (!transport_.authenticating() &&
            std::any_of(std::begin(a.signature), std::end(a.signature),
                        [](auto b) { return b != 0; }))
          ++signed_but_unchecked_;
        if (servers_.size() >= kMaxQueued && !servers_.count(a.server_id)) return;
        auto [it, first] = servers_.try_emplace(a.server_id, ServerSeen{Clock::now(), a.boot_us});
        if (!first && a.boot_us >= it->second.boot_us) it->second = {Clock::now(), a.boot_us};
      });
  // With a secret, the server's hint (unsigned: it names nobody) fails our check; it is still
  // worth reporting.
  transport_.on_unauthenticated([this](const std::string& channel, const std::uint8_t* d, int n) {
    if (channel != protocol::kError) return;
    if (auto e = protocol::decode<olympics::error_t>(d, n); e && e->code == "UNAUTHENTICATED")
      ++authentication_hints_;
  });
}

void Connection::report_mismatch_if_stuck() {
  if (mismatch_reported_ || answered_ || !first_sent_ || Clock::now() - *first_sent_ < seconds(1))
    return;
  const std::string hint = silence_hint();
  if (hint.empty()) return;
  mismatch_reported_ = true;
  std::fprintf(stderr, "olympics client %s: no answer yet%s\n", client_id_.c_str(), hint.c_str());
}

void Connection::pump(Clock::time_point until) {
  int ms = static_cast<int>(
      std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now()).count());
  transport_.handle(std::max(0, std::min(ms, 10)));
  report_mismatch_if_stuck();
}

void Connection::drain() {
  while (transport_.handle(0)) {
  }
}

olympics::match_request_t Connection::request_message(const MatchRequest& r,
                                                      const std::string& request_id) {
  olympics::match_request_t req;
  req.protocol_version = protocol::kProtocolVersion;
  req.request_id = request_id;
  req.server_id = r.server_id;
  req.sport = r.sport;
  req.mode = r.mode;
  req.seed = r.seed;
  req.time_limit_s = static_cast<float>(r.time_limit_s);
  req.realtime = r.realtime;
  req.options = r.options;
  return req;
}

void Connection::send_request(const olympics::match_request_t& request) {
  pending_requests_.insert(request.request_id);
  if (!first_sent_) first_sent_ = Clock::now();
  transport_.publish(protocol::kRequest, request);
}

std::optional<olympics::match_created_t> Connection::take_created(const std::string& request_id) {
  auto it = created_.find(request_id);
  if (it == created_.end()) return std::nullopt;
  auto created = std::move(it->second);
  created_.erase(it);
  pending_requests_.erase(request_id);
  return created;
}

// A server's error about a request starts "request <id>: " (and names no client); naming the id
// elsewhere in the text proves nothing (another request's id may contain it).
static bool answers_request(const olympics::error_t& e, const std::string& request_id) {
  return e.client_id.empty() && e.message.rfind("request " + request_id + ":", 0) == 0;
}

// Only an error that names what this client sent is acted on: one of its pending requests, or
// its own id with a match it joined or plays (or none: a refused bundle of its own). With a
// secret the transport has already dropped every error the server did not sign. Errors for
// other clients are none of its business; those naming this client with a match it does not
// hold are counted (ignored_errors()): a server never sends them, so something else did.
void Connection::on_error(const olympics::error_t& e) {
  if (e.code == "UNAUTHENTICATED") {  // a hint naming nobody (docs/security.md): report only
    ++authentication_hints_;
    return;
  }
  bool mine = false;
  for (const auto& id : pending_requests_) mine = mine || answers_request(e, id);
  if (e.client_id == client_id_)
    mine =
        e.match_id.empty() || observation_routes_.count(e.match_id) || watched_.count(e.match_id);
  if (mine) return push_bounded(errors_, e, kMaxQueued);
  if (e.client_id == client_id_) ++ignored_errors_;
}

std::optional<olympics::error_t> Connection::take_request_error(const std::string& request_id) {
  for (auto it = errors_.begin(); it != errors_.end(); ++it)
    if (answers_request(*it, request_id)) {
      auto e = std::move(*it);
      errors_.erase(it);
      return e;
    }
  return std::nullopt;
}

void Connection::send_join(const std::string& match_id, const std::vector<int>& slots) {
  olympics::join_t j;
  j.protocol_version = protocol::kProtocolVersion;
  j.match_id = match_id;
  j.client_id = client_id_;
  j.agent_name = options_.agent_name;
  j.policy_id = options_.policy_id;
  j.policy_version = options_.policy_version;
  j.num_slots = static_cast<int>(slots.size());
  j.slots = slots;
  listen_for_observations(match_id);
  if (!first_sent_) first_sent_ = Clock::now();
  transport_.publish(protocol::kJoin, j);
}

void Connection::listen_for_observations(const std::string& match_id) {
  if (observation_routes_.count(match_id)) return;  // a join sent again
  auto& route = observation_routes_[match_id];
  if (!exact_observation_channels_) return;  // the pattern subscription hears it
  route.subscription = transport_.subscribe(
      protocol::obs_channel(match_id),
      [this, match_id](const std::string&, const std::uint8_t* data, int size) {
        on_observation_message(match_id, data, size);
      });
}

void Connection::on_observation_message(const std::string& match_id, const std::uint8_t* data,
                                        int size) {
  if (!observation_routes_.count(match_id)) return;  // not ours, or a match already left
  if (auto batch = protocol::decode<olympics::observation_batch_t>(data, size))
    deliver(match_id, std::move(*batch));
  else
    transport_.count_malformed();
}

void Connection::deliver(const std::string& match_id, olympics::observation_batch_t&& batch) {
  auto it = observation_routes_.find(match_id);
  if (it == observation_routes_.end() || batch.client_id != client_id_) return;
  if (it->second.handler) return it->second.handler(std::move(batch));
  push_bounded(it->second.held, std::move(batch), kMaxHeld);
}

std::optional<JoinReply> Connection::take_join_reply(const std::string& match_id) {
  auto it = join_replies_.find(match_id);
  if (it == join_replies_.end()) return std::nullopt;
  auto reply = std::move(it->second);
  join_replies_.erase(it);
  if (!reply.accepted) forget_observations(match_id);
  return reply;
}

std::optional<olympics::error_t> Connection::fatal_error(const std::string& match_id,
                                                         bool joining) const {
  for (const auto& e : errors_) {
    if ((e.code == "UNKNOWN_MATCH" || e.code == "STORE_FAILED") && e.match_id == match_id) return e;
    if (joining && (e.code == "UPGRADE" || e.code == "UNKNOWN_MATCH") &&
        (e.match_id.empty() || e.match_id == match_id))
      return e;
  }
  return std::nullopt;
}

void Connection::watch(const std::string& match_id) { watched_.emplace(match_id, std::nullopt); }

const olympics::match_result_t* Connection::result(const std::string& match_id) const {
  auto it = watched_.find(match_id);
  return it != watched_.end() && it->second ? &*it->second : nullptr;
}

void Connection::forget(const std::string& match_id) {
  watched_.erase(match_id);
  std::erase_if(errors_, [&](const olympics::error_t& e) { return e.match_id == match_id; });
}

std::optional<Connection::ServerSeen> Connection::server(const std::string& server_id) const {
  auto it = servers_.find(server_id);
  if (it == servers_.end()) return std::nullopt;
  return it->second;
}

void Connection::on_observations(const std::string& match_id, ObservationHandler handler) {
  listen_for_observations(match_id);  // a session made without a join of this connection's
  auto& route = observation_routes_[match_id];
  route.handler = std::move(handler);
  for (auto& batch : route.held) route.handler(std::move(batch));
  route.held.clear();
}

void Connection::forget_observations(const std::string& match_id) {
  auto it = observation_routes_.find(match_id);
  if (it == observation_routes_.end()) return;
  if (it->second.subscription >= 0) transport_.unsubscribe(it->second.subscription);
  observation_routes_.erase(it);
}

double Connection::resend_interval_s() const {
  constexpr double kMaxS = 1.0;  // a round trip longer than this is a stall, not a pace
  return std::clamp(2 * longest_round_trip_s_, options_.resend_interval_s,
                    std::max(kMaxS, options_.resend_interval_s));
}

void Connection::note_round_trip(double seconds) {
  const auto now = Clock::now();
  longest_round_trip_s_ *=
      std::exp(-std::chrono::duration<double>(now - longest_round_trip_at_).count());
  if (seconds >= longest_round_trip_s_) longest_round_trip_s_ = seconds;
  longest_round_trip_at_ = now;
}

std::optional<Assignment> Connection::take_assignment(const std::string& learner) {
  for (auto it = assignments_.begin(); it != assignments_.end(); ++it) {
    if (it->learner != learner) continue;
    Assignment a = *it;
    assigned_matches_.insert(a.match_id);
    assignments_.erase(it);
    return a;
  }
  return std::nullopt;
}

std::string Connection::silence_hint() const {
  std::string hint;
  if (authentication_hints_ > 0)
    hint += "; a server answered UNAUTHENTICATED " + std::to_string(authentication_hints_) +
            " time(s) (messages from here failed its signature check): this client's secret "
            "(--secret) is not the server's, or one side runs unsigned";
  if (transport_.authenticating() && transport_.unauthenticated() > 0)
    hint += "; " + std::to_string(transport_.unauthenticated()) +
            " message(s) heard here failed the signature check: the servers may use another "
            "secret than this client's, or none";
  if (!transport_.authenticating() && signed_but_unchecked_ > 0)
    hint += "; " + std::to_string(signed_but_unchecked_) +
            " signed announcement(s) heard: the servers use a secret and this client has none "
            "(--secret FILE or $OLYMPICS_SECRET_FILE)";
  if (transport_.authenticating() && transport_.stale() > 0)
    hint += "; " + std::to_string(transport_.stale()) +
            " message(s) were sent too long ago by their sender's clock: keep the hosts' clocks "
            "in step (NTP)";
  return hint.empty() ? hint : hint + " (docs/security.md)";
}

std::vector<olympics::error_t> Connection::take_errors() {
  std::vector<olympics::error_t> out(errors_.begin(), errors_.end());
  errors_.clear();
  return out;
}

}  // namespace olympics::client
