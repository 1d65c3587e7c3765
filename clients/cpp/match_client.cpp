#include "match_client.h"

#include <unistd.h>

#include <random>

#include "channels.h"
#include "olympics/action_batch_t.hpp"
#include "olympics/heartbeat_t.hpp"
#include "olympics/join_reply_t.hpp"
#include "olympics/join_t.hpp"
#include "olympics/league_assignment_t.hpp"
#include "olympics/match_request_t.hpp"
#include "olympics/observation_batch_t.hpp"
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

std::chrono::steady_clock::duration seconds(double s) {
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(s));
}

// A match description a policy can rely on: the blocks add up to the observation, sizes are sane.
bool described_consistently(const olympics::match_created_t& m) {
  long blocks = 0;
  for (int size : m.obs_block_sizes) blocks += size;
  return m.obs_size > 0 && m.obs_size <= 1'000'000 && blocks == m.obs_size && m.action_size > 0 &&
         m.action_size <= 100'000 && m.control_hz > 0;
}

}  // namespace

bool Observation::all_done() const {
  for (bool d : done)
    if (!d) return false;
  return true;
}

MatchClient::MatchClient(const ClientOptions& options)
    : options_(options),
      client_id_(options.agent_name + "-" + random_id()),
      transport_({options.lcm_url, options.drop_rate, options.drop_seed,
                  protocol::load_secret(options.secret_file)}) {
  transport_.subscribe_to<olympics::match_created_t>(
      protocol::kCreated, [this](const std::string&, const olympics::match_created_t& m) {
        if (!pending_request_id_.empty() && m.request_id == pending_request_id_) created_ = m;
      });
  transport_.subscribe_to<olympics::join_reply_t>(
      protocol::kJoinReply, [this](const std::string&, const olympics::join_reply_t& m) {
        if (m.client_id != client_id_) return;
        if (m.accepted && !described_consistently(m.match)) return transport_.count_malformed();
        join_accepted_ = m.accepted;
        join_refusal_ = m.reason;
        if (m.accepted) match_ = m.match;
      });
  transport_.subscribe_to<olympics::error_t>(
      protocol::kError, [this](const std::string&, const olympics::error_t& m) {
        const bool about_my_request = m.client_id.empty() && !pending_request_id_.empty() &&
                                      m.message.find(pending_request_id_) != std::string::npos;
        if ((m.client_id == client_id_ || about_my_request) && errors_.size() < kMaxQueued)
          errors_.push_back(m);
      });
  transport_.subscribe_to<olympics::league_assignment_t>(
      protocol::kLeague, [this](const std::string&, const olympics::league_assignment_t& a) {
        for (const auto& known : assigned_matches_)
          if (known == a.match_id) return;
        for (const auto& queued : assignments_)
          if (queued.match_id == a.match_id) return;
        if (assignments_.size() >= kMaxQueued) assignments_.erase(assignments_.begin());
        assignments_.push_back({a.league, a.learner, a.match_id, a.opponent, a.game, a.slots});
      });
  transport_.subscribe_to<olympics::match_result_t>(
      protocol::kResult, [this](const std::string&, const olympics::match_result_t& m) {
        if (joined_ && m.match_id == match_.match_id) result_ = m;
      });
  transport_.subscribe_to<olympics::server_announce_t>(
      protocol::kAnnounce, [this](const std::string&, const olympics::server_announce_t& a) {
        if (servers_.size() < kMaxQueued || servers_.count(a.server_id))
          servers_[a.server_id] = {Clock::now(), a.boot_us};
      });
}

void MatchClient::fail_if_match_lost() {
  // A joined client passed the version and signature checks: in play, only these end it.
  for (const auto& e : errors_)
    if ((e.code == "UNKNOWN_MATCH" || e.code == "STORE_FAILED") && e.match_id == match_.match_id)
      throw MatchError(e.code, e.message);
  if (!joined_) return;
  const auto seen = servers_.find(match_.server_id);
  const auto silence = seconds(options_.server_silence_s);
  if (seen == servers_.end()) {
    if (Clock::now() - joined_at_ > silence)
      throw MatchError("SERVER_GONE", "server " + match_.server_id + " of match " +
                                          match_.match_id + " has not announced itself since " +
                                          "the join: it is gone, or on another network");
    return;
  }
  if (match_server_boot_ == 0) match_server_boot_ = seen->second.boot_us;
  if (seen->second.boot_us != match_server_boot_)
    throw MatchError("SERVER_RESTARTED", "server " + match_.server_id + " restarted: match " +
                                             match_.match_id + " is lost");
  if (Clock::now() - seen->second.when > silence)
    throw MatchError("SERVER_GONE", "server " + match_.server_id +
                                        " stopped announcing itself: "
                                        "match " +
                                        match_.match_id + " is lost");
}

void MatchClient::pump(Clock::time_point until) {
  int ms = static_cast<int>(
      std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now()).count());
  transport_.handle(std::max(0, std::min(ms, 10)));
}

std::vector<olympics::error_t> MatchClient::take_errors() {
  std::vector<olympics::error_t> out;
  out.swap(errors_);
  return out;
}

olympics::match_created_t MatchClient::request_match(const MatchRequest& r, double timeout_s) {
  olympics::match_request_t req;
  req.protocol_version = protocol::kProtocolVersion;
  req.request_id = r.request_id.empty() ? client_id_ + "-req" : r.request_id;
  req.server_id = r.server_id;
  req.sport = r.sport;
  req.mode = r.mode;
  req.seed = r.seed;
  req.time_limit_s = static_cast<float>(r.time_limit_s);
  req.realtime = r.realtime;
  req.options = r.options;
  pending_request_id_ = req.request_id;
  created_.reset();
  errors_.clear();
  const auto deadline = Clock::now() + seconds(timeout_s);
  auto next_send = Clock::now();
  while (!created_) {
    auto now = Clock::now();
    if (now >= deadline)
      throw MatchError("TIMEOUT", "no server answered the request for " + r.sport + " " + r.mode +
                                      " within " + std::to_string(timeout_s) +
                                      " s; is olympics-server running on " + transport_.url() +
                                      "?");
    if (now >= next_send) {
      transport_.publish(protocol::kRequest, req);
      next_send = now + seconds(0.25);
    }
    for (const auto& e : errors_) throw MatchError(e.code, e.message);
    pump(std::min(deadline, next_send));
  }
  pending_request_id_.clear();
  return *created_;
}

Assignment MatchClient::wait_assignment(const std::string& learner, double timeout_s) {
  const auto deadline = Clock::now() + seconds(timeout_s);
  for (;;) {
    for (auto it = assignments_.begin(); it != assignments_.end(); ++it) {
      if (it->learner != learner) continue;
      Assignment a = *it;
      assigned_matches_.push_back(a.match_id);
      assignments_.erase(it);
      return a;
    }
    if (Clock::now() >= deadline)
      throw MatchError("TIMEOUT", "no league assigned a match to learner \"" + learner +
                                      "\" within " + std::to_string(timeout_s) +
                                      " s; is it an entrant (live:" + learner + ")?");
    pump(deadline);
  }
}

olympics::match_created_t MatchClient::join(const std::string& match_id,
                                            const std::vector<int>& slots, double timeout_s) {
  olympics::join_t j;
  j.protocol_version = protocol::kProtocolVersion;
  j.match_id = match_id;
  j.client_id = client_id_;
  j.agent_name = options_.agent_name;
  j.policy_id = options_.policy_id;
  j.policy_version = options_.policy_version;
  j.num_slots = static_cast<int>(slots.size());
  j.slots = slots;
  join_accepted_.reset();
  const auto deadline = Clock::now() + seconds(timeout_s);
  auto next_send = Clock::now();
  while (!join_accepted_) {
    auto now = Clock::now();
    if (now >= deadline)
      throw MatchError("TIMEOUT", "no answer to the join of match " + match_id + " within " +
                                      std::to_string(timeout_s) + " s");
    for (const auto& e : errors_)
      if ((e.code == "UNKNOWN_MATCH" || e.code == "UNAUTHENTICATED" || e.code == "UPGRADE") &&
          (e.match_id.empty() || e.match_id == match_id))
        throw MatchError(e.code, e.message);
    if (now >= next_send) {
      transport_.publish(protocol::kJoin, j);
      next_send = now + seconds(0.25);
    }
    pump(std::min(deadline, next_send));
  }
  if (!*join_accepted_) {
    std::string code = "REFUSED";
    for (const auto& e : errors_) code = e.code;
    errors_.clear();
    throw MatchError(code, join_refusal_);
  }
  // A client may play one match after another: forget the previous one.
  slots_ = slots;
  std::sort(slots_.begin(), slots_.end());
  joined_ = true;
  result_.reset();
  latest_.reset();
  last_returned_tick_ = -1;
  last_action_bytes_.clear();
  if (obs_subscription_ >= 0) transport_.unsubscribe(obs_subscription_);
  obs_subscription_ = transport_.subscribe_to<olympics::observation_batch_t>(
      match_.obs_channel, [this](const std::string&, const olympics::observation_batch_t& b) {
        if (b.client_id != client_id_ || b.match_id != match_.match_id ||
            b.tick <= last_returned_tick_)
          return;  // ours, and new
        // The shape the match described: another one would send a policy out of bounds.
        if (b.slots != slots_ || b.obs_size != match_.obs_size) return transport_.count_malformed();
        if (latest_ && latest_->tick >= b.tick) return;
        Observation o;
        o.tick = b.tick;
        o.slots = b.slots;
        o.obs = b.obs;
        o.reward = b.reward;
        o.term_names = b.term_names;
        o.terms = b.terms;
        o.done.assign(b.done.begin(), b.done.end());
        o.truncated.assign(b.truncated.begin(), b.truncated.end());
        o.info = b.info;
        latest_ = std::move(o);
      });
  last_heartbeat_ = Clock::now();
  joined_at_ = Clock::now();
  match_server_boot_ = 0;
  errors_.clear();
  return match_;
}

void MatchClient::heartbeat_if_due() {
  if (Clock::now() - last_heartbeat_ < seconds(options_.heartbeat_interval_s)) return;
  olympics::heartbeat_t h;
  h.protocol_version = protocol::kProtocolVersion;
  h.match_id = match_.match_id;
  h.client_id = client_id_;
  h.timestamp_us = std::chrono::duration_cast<std::chrono::microseconds>(
                       std::chrono::system_clock::now().time_since_epoch())
                       .count();
  transport_.publish(protocol::kHeartbeat, h);
  last_heartbeat_ = Clock::now();
}

// Our last action may have been lost: if the next observation has not come, send it again.
void MatchClient::resend_if_due() {
  if (last_action_bytes_.empty() || Clock::now() - last_send_ < seconds(options_.resend_interval_s))
    return;
  transport_.publish_raw(match_.action_channel, last_action_bytes_.data(),
                         static_cast<int>(last_action_bytes_.size()));
  last_send_ = Clock::now();
}

std::optional<Observation> MatchClient::next(double timeout_s) {
  if (!joined_) throw MatchError("NOT_JOINED", "join a match before asking for observations");
  const auto deadline = Clock::now() + seconds(timeout_s);
  while (!latest_) {
    if (result_) return std::nullopt;
    if (Clock::now() >= deadline)
      throw MatchError("TIMEOUT", "no observation from match " + match_.match_id + " for " +
                                      std::to_string(timeout_s) + " s: the server may be gone");
    fail_if_match_lost();
    heartbeat_if_due();
    resend_if_due();
    pump(deadline);
  }
  Observation o = std::move(*latest_);
  latest_.reset();
  last_returned_tick_ = o.tick;
  return o;
}

void MatchClient::act(int tick, const std::vector<std::vector<float>>& actions) {
  if (actions.size() != slots_.size())
    throw MatchError("BAD_ACTION", "act() got " + std::to_string(actions.size()) + " actions for " +
                                       std::to_string(slots_.size()) + " slots");
  olympics::action_batch_t b;
  b.protocol_version = protocol::kProtocolVersion;
  b.match_id = match_.match_id;
  b.client_id = client_id_;
  b.seq = ++seq_;
  b.tick = tick;
  b.num_slots = static_cast<int>(slots_.size());
  b.slots = slots_;
  b.action_size = actions.empty() ? 0 : static_cast<int>(actions[0].size());
  b.actions = actions;
  last_action_bytes_ = protocol::encode(b);
  last_action_tick_ = tick;
  resend_gap_s_ = options_.resend_interval_s;
  transport_.publish_raw(match_.action_channel, last_action_bytes_.data(),
                         static_cast<int>(last_action_bytes_.size()));
  last_send_ = Clock::now();
}

const olympics::match_result_t& MatchClient::wait_result(double timeout_s) {
  const auto deadline = Clock::now() + seconds(timeout_s);
  while (!result_) {
    if (Clock::now() >= deadline)
      throw MatchError("TIMEOUT", "no result for match " + match_.match_id + " within " +
                                      std::to_string(timeout_s) + " s");
    fail_if_match_lost();
    heartbeat_if_due();
    resend_if_due();  // a server that has finished answers a resent action with the result
    pump(deadline);
  }
  pump(Clock::now());  // an error about storing it comes just before the result
  fail_if_match_lost();
  return *result_;
}

}  // namespace olympics::client
