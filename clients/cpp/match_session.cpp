#include "match_session.h"

#include <algorithm>

#include "channels.h"
#include "match_id.h"
#include "olympics/action_batch_t.hpp"
#include "olympics/heartbeat_t.hpp"
#include "olympics/observation_batch_t.hpp"
#include "version.h"

namespace olympics::client {

bool Observation::all_done() const {
  return std::all_of(done.begin(), done.end(), [](bool d) { return d; });
}

MatchSession::MatchSession(Connection& connection, olympics::match_created_t match,
                           std::vector<int> slots)
    : connection_(connection), match_(std::move(match)), slots_(std::move(slots)) {
  std::sort(slots_.begin(), slots_.end());
  connection_.watch(match_.match_id);
  connection_.on_observations(
      match_.match_id, [this](olympics::observation_batch_t&& b) { on_observation(std::move(b)); });
  joined_at_ = last_heartbeat_ = Clock::now();
}

void MatchSession::on_observation(olympics::observation_batch_t&& b) {
  if (b.client_id != connection_.client_id() || b.match_id != match_.match_id) return;
  // New: a later tick, or the same tick ending the match (a forfeit ends it between
  // ticks, so its final batch repeats the tick of the one before).
  const bool ends = std::all_of(b.done.begin(), b.done.end(), [](auto d) { return d; });
  if (b.tick < last_taken_tick_ || (b.tick == last_taken_tick_ && (last_taken_done_ || !ends)))
    return;
  // The shape the match described: another one would send a policy out of bounds.
  if (b.slots != slots_ || b.obs_size != match_.obs_size)
    return connection_.transport().count_malformed();
  if (latest_ && (latest_->tick > b.tick || (latest_->tick == b.tick && !ends))) return;
  if (!resent_ && !last_action_bytes_.empty() && b.tick == last_action_tick_ + 1)
    connection_.note_round_trip(std::chrono::duration<double>(Clock::now() - acted_at_).count());
  Observation o;
  o.tick = b.tick;
  o.slots = b.slots;
  o.obs = std::move(b.obs);
  o.reward = std::move(b.reward);
  o.term_names = std::move(b.term_names);
  o.terms = std::move(b.terms);
  o.done.assign(b.done.begin(), b.done.end());
  o.truncated.assign(b.truncated.begin(), b.truncated.end());
  o.info = std::move(b.info);
  latest_ = std::move(o);
}

MatchSession::~MatchSession() {
  connection_.forget_observations(match_.match_id);
  connection_.forget(match_.match_id);
}

std::optional<Observation> MatchSession::take_observation() {
  if (!latest_) return std::nullopt;
  Observation o = std::move(*latest_);
  latest_.reset();
  last_taken_tick_ = o.tick;
  last_taken_done_ = o.all_done();
  return o;
}

void MatchSession::act(int tick, const std::vector<std::vector<float>>& actions) {
  prepare_action(tick, actions);
  connection_.transport().publish_raw(match_.action_channel, last_action_bytes_.data(),
                                      static_cast<int>(last_action_bytes_.size()));
}

const std::vector<std::uint8_t>& MatchSession::prepare_action(
    int tick, const std::vector<std::vector<float>>& actions) {
  if (actions.size() != slots_.size())
    throw MatchError("BAD_ACTION", "act() got " + std::to_string(actions.size()) + " actions for " +
                                       std::to_string(slots_.size()) + " slots");
  olympics::action_batch_t b;
  b.protocol_version = protocol::kProtocolVersion;
  b.match_id = match_.match_id;
  b.client_id = connection_.client_id();
  b.seq = ++seq_;
  b.tick = tick;
  b.num_slots = static_cast<int>(slots_.size());
  b.slots = slots_;
  b.action_size = actions.empty() ? 0 : static_cast<int>(actions[0].size());
  b.actions = actions;
  last_action_bytes_ = protocol::encode(b);
  last_action_tick_ = tick;
  last_send_ = acted_at_ = Clock::now();
  resend_gap_s_ = connection_.resend_interval_s();
  resent_ = false;
  return last_action_bytes_;
}

void MatchSession::maintain() {
  fail_if_lost();
  const auto now = Clock::now();
  const auto& options = connection_.options();
  // An action is heard as much as a heartbeat: one goes only when neither went for a while
  // (a client playing many matches would otherwise send one datagram per match for nothing).
  if (now - std::max(last_heartbeat_, last_send_) >= seconds(options.heartbeat_interval_s)) {
    olympics::heartbeat_t h;
    h.protocol_version = protocol::kProtocolVersion;
    h.match_id = match_.match_id;
    h.client_id = connection_.client_id();
    h.timestamp_us = std::chrono::duration_cast<std::chrono::microseconds>(
                         std::chrono::system_clock::now().time_since_epoch())
                         .count();
    connection_.transport().publish(protocol::kHeartbeat, h);
    last_heartbeat_ = now;
  }
  // Our last action may have been lost: while the next observation has not come, send it
  // again (a server that has finished answers it with the result), less often each time.
  constexpr double kMaxResendGapS = 0.25;
  if (!latest_ && !last_action_bytes_.empty() && now - last_send_ >= seconds(resend_gap_s_)) {
    connection_.transport().publish_raw(match_.action_channel, last_action_bytes_.data(),
                                        static_cast<int>(last_action_bytes_.size()));
    last_send_ = now;
    resend_gap_s_ = std::max(resend_gap_s_, std::min(2 * resend_gap_s_, kMaxResendGapS));
    resent_ = true;
  }
}

const olympics::match_result_t* MatchSession::result() const {
  return connection_.result(match_.match_id);
}

bool MatchSession::ended_without_final_observation() {
  // The result came; the final observation may still be on its way (resent on request). 0.5 s
  // was too short for a CPU-starved client at 10% loss: python.vector_env's lossy run then took
  // the substitute in 1 of 10-15 runs beside two CPU hogs.
  constexpr double kGraceS = 2.0;
  if (latest_ || last_taken_done_ || !result()) return false;
  if (!result_seen_at_) result_seen_at_ = Clock::now();
  return Clock::now() - *result_seen_at_ > seconds(kGraceS);
}

void MatchSession::fail_if_lost() {
  // A joined client passed the version and signature checks: in play, only these end it.
  if (auto e = connection_.fatal_error(match_.match_id)) throw MatchError(e->code, e->message);
  const auto seen = connection_.server(match_.server_id);
  const auto silence = seconds(connection_.options().server_silence_s);
  if (!seen) {
    if (Clock::now() - joined_at_ > silence)
      throw MatchError("SERVER_GONE", "server " + match_.server_id + " of match " +
                                          match_.match_id + " has not announced itself since " +
                                          "the join: it is gone, or on another network");
    return;
  }
  // The boot that hosts the match is in its id; an announcement of a later boot is a restart,
  // of an earlier one a replay of a stopped process's (ignored).
  if (server_boot_ == 0) server_boot_ = protocol::match_boot_ms(match_.match_id).value_or(-1);
  if (server_boot_ < 0) server_boot_ = seen->boot_us / 1000;  // an id of another form
  if (seen->boot_us / 1000 > server_boot_)
    throw MatchError("SERVER_RESTARTED", "server " + match_.server_id + " restarted: match " +
                                             match_.match_id + " is lost");
  if (Clock::now() - seen->when > silence)
    throw MatchError("SERVER_GONE", "server " + match_.server_id +
                                        " stopped announcing itself: match " + match_.match_id +
                                        " is lost");
}

}  // namespace olympics::client
