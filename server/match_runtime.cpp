#include "match_runtime.h"

#include <algorithm>
#include <cstdio>

#include "channels.h"
#include "olympics/error_t.hpp"
#include "olympics/join_reply_t.hpp"
#include "olympics/match_start_t.hpp"
#include "olympics/observation_batch_t.hpp"
#include "validation.h"
#include "version.h"

namespace olympics::server {
namespace {

using Seconds = std::chrono::duration<double>;

MatchRuntime::Clock::duration seconds(double s) {
  return std::chrono::duration_cast<MatchRuntime::Clock::duration>(Seconds(s));
}

constexpr double kMaxResendGapS = 0.25;

}  // namespace

MatchRuntime::MatchRuntime(MatchIdentity identity, RuntimeSettings settings,
                           std::unique_ptr<sports::SportMatch> game, protocol::Transport& transport,
                           std::unique_ptr<TrafficLog> log)
    : identity_(std::move(identity)),
      settings_(settings),
      game_(std::move(game)),
      transport_(transport),
      log_(std::move(log)),
      created_at_(Clock::now()) {
  const int n = game_->slot_count();
  auto& d = description_;
  d.protocol_version = protocol::kProtocolVersion;
  d.server_id = identity_.server_id;
  d.match_id = identity_.match_id;
  d.sport = identity_.sport;
  d.mode = identity_.settings.mode;
  d.seed = static_cast<std::int64_t>(identity_.settings.seed);
  d.realtime = identity_.realtime;
  d.num_slots = n;
  for (int s = 0; s < n; ++s) d.slot_team.push_back(game_->team_of(s));
  d.obs_size = game_->obs_size();
  d.action_size = game_->action_size();
  d.obs_channel = protocol::obs_channel(identity_.match_id);
  d.action_channel = protocol::action_channel(identity_.match_id);
  d.control_hz = static_cast<std::int16_t>(game_->control_hz());  // the match's own rate
  d.time_limit_s = static_cast<float>(game_->time_limit_s());
  d.options = identity_.settings.options.dump();
  for (const auto& block : game_->layout().observation) {
    d.obs_block_names.push_back(block.name);
    d.obs_block_sizes.push_back(block.size);
    d.obs_block_field_counts.push_back(static_cast<int>(block.fields.size()));
    for (const auto& field : block.fields) {
      d.obs_field_names.push_back(field.name);
      d.obs_field_sizes.push_back(field.size);
    }
  }
  d.num_obs_blocks = static_cast<int>(d.obs_block_names.size());
  d.num_obs_fields = static_cast<int>(d.obs_field_names.size());
  slot_owner_.assign(n, -1);
  current_.assign(n, std::vector<float>(game_->action_size(), 0.0f));
  pending_ = current_;
  has_pending_.assign(n, 0);
  newest_action_tick_.assign(n, -1);
}

template <typename Msg>
void MatchRuntime::send(const std::string& channel, const Msg& msg, bool log_whole) {
  const auto buf = protocol::encode(msg);
  if (log_) {
    log_->write(channel, buf.data(), static_cast<int>(buf.size()));
    if (log_whole) log_->flush();
  }
  transport_.publish_raw(channel, buf.data(), static_cast<int>(buf.size()));
}

void MatchRuntime::error(const std::string& client_id, const std::string& code,
                         const std::string& message) {
  olympics::error_t e;
  e.protocol_version = protocol::kProtocolVersion;
  e.server_id = identity_.server_id;
  e.match_id = identity_.match_id;
  e.client_id = client_id;
  e.code = code;
  e.message = message;
  if (const long n = error_logs_[code].note())
    std::fprintf(
        stderr, "[%s] %s from %s: %s%s\n", identity_.match_id.c_str(), code.c_str(),
        client_id.empty() ? "?" : client_id.c_str(), message.c_str(),
        n > 1 ? (" (and " + std::to_string(n - 1) + " more in the last second)").c_str() : "");
  const int c = client_index(client_id);
  if (c >= 0 && !may_answer(c, Clock::now())) return;
  send(protocol::kError, e);
}

bool MatchRuntime::may_answer(int c, Clock::time_point now) {
  Client& k = clients_[c];
  k.answer_tokens = std::min(
      kAnswersPerS,
      k.answer_tokens + kAnswersPerS * std::chrono::duration<double>(now - k.answer_at).count());
  k.answer_at = now;
  if (k.answer_tokens < 1) return false;
  k.answer_tokens -= 1;
  return true;
}

// A client whose every slot is done (its humanoids are out) is not waited for: its actions
// would change nothing.
bool MatchRuntime::still_playing(const Client& k) const {
  for (int s : k.slots)
    if (!game_->outcome().done[s]) return true;
  return false;
}

std::vector<int> MatchRuntime::all_clients() const {
  std::vector<int> all(clients_.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  return all;
}

int MatchRuntime::client_index(const std::string& client_id) const {
  for (size_t i = 0; i < clients_.size(); ++i)
    if (clients_[i].id == client_id) return static_cast<int>(i);
  return -1;
}

void MatchRuntime::handle(const std::string& channel, const std::vector<std::uint8_t>& bytes,
                          Clock::time_point now, bool bundled) {
  if (log_) log_->write(channel, bytes.data(), static_cast<int>(bytes.size()));
  auto malformed = [&](const char* type) {
    transport_.count_malformed();
    if (!transport_.may_complain()) return;
    error("", "MALFORMED",
          "could not decode a " + std::string(type) + " of " + std::to_string(bytes.size()) +
              " bytes on " + channel +
              ": truncated, corrupted, or sent by a client built for another protocol version "
              "(upgrade it to protocol " +
              std::to_string(protocol::kProtocolVersion) + ")");
  };
  const int size = static_cast<int>(bytes.size());
  if (channel == protocol::kJoin) {
    if (auto m = protocol::decode<olympics::join_t>(bytes.data(), size))
      on_join(*m, now);
    else
      malformed("join_t");
  } else if (channel == protocol::kHeartbeat) {
    if (auto m = protocol::decode<olympics::heartbeat_t>(bytes.data(), size))
      on_heartbeat(*m, now);
    else
      malformed("heartbeat_t");
  } else {
    auto m = protocol::decode<olympics::action_batch_t>(bytes.data(), size);
    // A bundle's part was routed by the match id the bundle gave it: it must say the same.
    if (m && (!bundled || m->match_id == identity_.match_id))
      on_actions(*m, now, bundled);
    else
      malformed("action_batch_t");
  }
}

void MatchRuntime::on_join(const olympics::join_t& join, Clock::time_point now) {
  olympics::join_reply_t reply;
  reply.protocol_version = protocol::kProtocolVersion;
  reply.match_id = identity_.match_id;
  reply.client_id = join.client_id;
  reply.match = description_;
  auto refuse = [&](const std::string& code, const std::string& why) {
    error(join.client_id, code, why);
    reply.accepted = false;
    reply.reason = why;
    send(protocol::kJoinReply, reply);
  };
  if (auto v = protocol::version_mismatch(join.protocol_version)) return refuse("UPGRADE", *v);
  if (join.client_id.empty()) return refuse("BAD_REQUEST", "join without a client_id");
  if (join.num_slots != static_cast<int>(join.slots.size()) || join.num_slots == 0)
    return refuse("BAD_REQUEST", "join names no slots, or num_slots does not match the array");

  int existing = client_index(join.client_id);
  std::vector<int> wanted(join.slots.begin(), join.slots.end());
  std::sort(wanted.begin(), wanted.end());
  if (existing >= 0) {  // a resent join: answer again, as long as it asks for the same slots
    if (wanted != clients_[existing].slots)
      return refuse("BAD_REQUEST",
                    "this client already joined slots that differ from this request");
    reply.accepted = true;
    if (!may_answer(existing, now)) return;  // asked again and again: answered a few times a second
    return send(protocol::kJoinReply, reply);
  }
  for (size_t i = 0; i < wanted.size(); ++i) {
    int s = wanted[i];
    if (s < 0 || s >= game_->slot_count())
      return refuse("UNKNOWN_SLOT", "slot " + std::to_string(s) + " does not exist; this " +
                                        identity_.sport + " " + identity_.settings.mode +
                                        " match has slots 0.." +
                                        std::to_string(game_->slot_count() - 1));
    if (i > 0 && wanted[i - 1] == s)
      return refuse("BAD_REQUEST", "slot " + std::to_string(s) + " named twice");
    if (slot_owner_[s] >= 0)
      return refuse("SLOT_TAKEN", "slot " + std::to_string(s) + " is already taken by agent \"" +
                                      clients_[slot_owner_[s]].agent + "\"; choose a free slot");
  }
  if (phase_ != Phase::Joining) return refuse("SLOT_TAKEN", "the match has already started");
  // Every observation message must fit one datagram.
  olympics::observation_batch_t probe;
  probe.num_slots = static_cast<int>(wanted.size());
  probe.slots.assign(wanted.size(), 0);
  probe.obs_size = game_->obs_size();
  probe.obs.assign(wanted.size(), std::vector<float>(game_->obs_size()));
  probe.reward.assign(wanted.size(), 0);
  probe.num_terms = static_cast<int>(game_->reward_terms().size());
  probe.term_names = game_->reward_terms();
  probe.terms.assign(wanted.size(), std::vector<float>(probe.num_terms));
  probe.done.assign(wanted.size(), false);
  probe.truncated.assign(wanted.size(), false);
  probe.info = std::string(2000, ' ');
  if (probe.getEncodedSize() > protocol::kMaxMessageBytes)
    return refuse("BAD_REQUEST",
                  "observations for " + std::to_string(wanted.size()) +
                      " slots would not fit one datagram; join fewer slots per client");

  Client c;
  c.id = join.client_id;
  c.agent = join.agent_name;
  c.policy = join.policy_id;
  c.policy_version = join.policy_version;
  c.slots = wanted;
  c.last_heard = now;
  clients_.push_back(c);
  for (int s : wanted) slot_owner_[s] = static_cast<int>(clients_.size()) - 1;
  reply.accepted = true;
  send(protocol::kJoinReply, reply);
  if (std::find(slot_owner_.begin(), slot_owner_.end(), -1) == slot_owner_.end()) start(now);
}

void MatchRuntime::start(Clock::time_point now) {
  phase_ = Phase::Running;
  started_at_ = now;
  started_wall_ = std::chrono::system_clock::now();
  olympics::match_start_t m;
  m.protocol_version = protocol::kProtocolVersion;
  m.match_id = identity_.match_id;
  m.start_time_us =
      std::chrono::duration_cast<std::chrono::microseconds>(started_wall_.time_since_epoch())
          .count();
  m.num_slots = game_->slot_count();
  m.agent_names = slot_agents();
  send(protocol::kStart, m);
  tick_deadline_ = now + seconds(settings_.action_deadline_s);
  resend_gap_s_ = settings_.resend_interval_s;
  next_resend_ = now + seconds(resend_gap_s_);
  next_realtime_tick_ = now + seconds(game_->control_dt());
  publish_observations(all_clients());
}

// The scene track begins with the first tick, not at the start: the start answers the last
// joiner and lets the host note the players, and should not wait for the track's header.
void MatchRuntime::begin_scene() {
  if (!scene_ || scene_started_) return;
  scene_started_ = true;
  record([&](SceneRecorder& r) {
    r.start(*game_, identity_.sport, scene_about(identity_header(slot_agents())));
  });
}

std::vector<std::string> MatchRuntime::slot_agents() const {
  std::vector<std::string> agents;
  for (int s = 0; s < game_->slot_count(); ++s) agents.push_back(clients_[slot_owner_[s]].agent);
  return agents;
}

// Who played what, as replays (and, through scene_about, scene tracks) record it.
nlohmann::json MatchRuntime::identity_header(const std::vector<std::string>& agents) const {
  return {{"match_id", identity_.match_id},
          {"server_id", identity_.server_id},
          {"server_version", protocol::kSoftwareVersion},
          {"protocol_version", protocol::kProtocolVersion},
          {"sport", identity_.sport},
          {"mode", identity_.settings.mode},
          {"seed", identity_.settings.seed},
          {"time_limit_s", identity_.settings.time_limit_s},
          {"options", identity_.settings.options},
          {"realtime", identity_.realtime},
          {"agents", agents}};
}

template <typename Step>
void MatchRuntime::record(Step step) {
  if (!scene_) return;
  try {
    step(*scene_);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "[%s] scene track dropped: %s\n", identity_.match_id.c_str(), e.what());
    scene_.reset();
  }
}

// A heartbeat counts only from a client of this match, in this protocol version; anything else
// is dropped and counted (answering every stray heartbeat would let one flood the network).
void MatchRuntime::on_heartbeat(const olympics::heartbeat_t& beat, Clock::time_point now) {
  if (protocol::version_mismatch(beat.protocol_version) || beat.match_id != identity_.match_id)
    return transport_.count_malformed();
  // One from no client of the match is a watcher's probe (a league asks about its games this
  // way): well formed, nothing to do while the match runs.
  const int c = client_index(beat.client_id);
  if (c >= 0) clients_[c].last_heard = now;
}

void MatchRuntime::on_actions(const olympics::action_batch_t& batch, Clock::time_point now,
                              bool bundled) {
  if (phase_ == Phase::Finished) {  // it missed the end: say it again (not over and over)
    const int k = client_index(batch.client_id);
    if (k < 0 || !may_answer(k, now)) return;
    if (auto it = final_batches_.find(batch.client_id); it != final_batches_.end())
      send(description_.obs_channel, it->second);
    return publish_result();
  }
  int c = client_index(batch.client_id);
  if (c < 0)
    return error(batch.client_id, "UNKNOWN_CLIENT",
                 "actions from a client that has not joined match " + identity_.match_id +
                     "; send a join_t on " + protocol::kJoin + " first");
  clients_[c].last_heard = now;
  clients_[c].bundled = bundled && outbox_;
  if (phase_ != Phase::Running)
    return error(batch.client_id, "FUTURE_TICK",
                 "the match has not started: not every slot is claimed yet");
  if (auto problem = protocol::check_action_batch(batch, game_->slot_count(), game_->action_size(),
                                                  clients_[c].slots))
    return error(batch.client_id, problem->code, problem->message);
  const int tick = game_->tick();
  if (batch.tick > tick)
    return error(batch.client_id, "FUTURE_TICK",
                 "action for tick " + std::to_string(batch.tick) + " but the match is at tick " +
                     std::to_string(tick) + "; answer the observation you were sent");
  if (!identity_.realtime && batch.tick < tick) {
    if (!may_answer(c, now)) return;
    if (batch.tick == tick - 1) {  // a resend: applied already, but the client missed tick t
      publish_observations({c});
      return;
    }
    publish_observations({c});  // it has fallen behind: show it where the match is
    return error(batch.client_id, "STALE_TICK",
                 "action for tick " + std::to_string(batch.tick) + " arrived at tick " +
                     std::to_string(tick) + " and was ignored");
  }
  if (identity_.realtime && batch.tick < tick - game_->control_hz())
    return error(batch.client_id, "STALE_TICK",
                 "action for tick " + std::to_string(batch.tick) +
                     " is over a second old at tick " + std::to_string(tick) + " and was ignored");
  // A realtime batch older than one taken for any of its slots came late (or is a replay):
  // applying it would put an old action back in force.
  for (int i = 0; i < batch.num_slots; ++i)
    if (batch.tick < newest_action_tick_[batch.slots[i]]) return;
  for (int i = 0; i < batch.num_slots; ++i) {
    pending_[batch.slots[i]] = batch.actions[i];
    has_pending_[batch.slots[i]] = 1;
    newest_action_tick_[batch.slots[i]] = batch.tick;
  }
  clients_[c].acted_this_tick = true;
  if (!identity_.realtime && std::all_of(clients_.begin(), clients_.end(), [&](const Client& k) {
        return k.acted_this_tick || !still_playing(k);
      }))
    advance(now);
}

MatchRuntime::Clock::time_point MatchRuntime::poll(Clock::time_point now) {
  if (phase_ == Phase::Finished) return now + std::chrono::hours(1);
  if (phase_ == Phase::Joining) {
    if (now - created_at_ >= seconds(settings_.join_timeout_s)) {
      game_->forfeit(-1, "cancelled: not every slot was claimed within " +
                             std::to_string(static_cast<int>(settings_.join_timeout_s)) + " s");
      finish(now);
      return now;
    }
    return created_at_ + seconds(settings_.join_timeout_s);
  }
  for (size_t c = 0; c < clients_.size(); ++c)
    if (still_playing(clients_[c]) &&
        now - clients_[c].last_heard >= seconds(settings_.silent_timeout_s)) {
      forfeit(static_cast<int>(c),
              "silent for " + std::to_string(settings_.silent_timeout_s) + " s", now);
      return now;
    }
  if (identity_.realtime) {
    while (phase_ == Phase::Running && now >= next_realtime_tick_) {
      advance(now);
      next_realtime_tick_ += seconds(game_->control_dt());
    }
    return next_realtime_tick_;
  }
  if (now >= tick_deadline_) {
    advance(now);
    return std::min(tick_deadline_, next_resend_);
  }
  if (now >= next_resend_) {  // republish tick t to whoever has not answered it
    std::vector<int> missing;
    for (size_t c = 0; c < clients_.size(); ++c)
      if (!clients_[c].acted_this_tick && still_playing(clients_[c]))
        missing.push_back(static_cast<int>(c));
    publish_observations(missing);
    resend_gap_s_ = std::min(2 * resend_gap_s_, kMaxResendGapS);  // back off while waiting
    next_resend_ = now + seconds(resend_gap_s_);
  }
  return std::min(tick_deadline_, next_resend_);
}

void MatchRuntime::advance(Clock::time_point now) {
  for (size_t c = 0; c < clients_.size(); ++c) {
    Client& k = clients_[c];
    k.missed_in_row = (k.acted_this_tick || !still_playing(k)) ? 0 : k.missed_in_row + 1;
    k.acted_this_tick = false;
    if (k.missed_in_row >= settings_.max_missed_ticks)
      return forfeit(static_cast<int>(c),
                     "sent no action for " + std::to_string(k.missed_in_row) + " ticks in a row",
                     now);
  }
  for (int s = 0; s < game_->slot_count(); ++s)
    if (has_pending_[s]) current_[s].swap(pending_[s]), has_pending_[s] = 0;  // else it repeats
  std::vector<std::span<const float>> actions;
  for (const auto& a : current_) {
    actions.emplace_back(a);
    replay_actions_.insert(replay_actions_.end(), a.begin(), a.end());
  }
  begin_scene();
  game_->step(actions);
  record([&](SceneRecorder& r) { r.tick(*game_); });
  tick_deadline_ = now + seconds(settings_.action_deadline_s);
  resend_gap_s_ = settings_.resend_interval_s;
  next_resend_ = now + seconds(resend_gap_s_);
  publish_observations(all_clients());
  if (game_->outcome().match_over) finish(now);
}

void MatchRuntime::publish_observations(const std::vector<int>& clients) {
  const auto& out = game_->outcome();
  nlohmann::json info = out.info;
  info["scores"] = out.scores;
  if (out.match_over) info["reason"] = out.reason, info["winner_team"] = out.winner_team;
  const std::string info_text = info.dump();
  for (int c : clients) {
    Client& k = clients_[c];
    olympics::observation_batch_t b;
    b.protocol_version = protocol::kProtocolVersion;
    b.match_id = identity_.match_id;
    b.client_id = k.id;
    b.seq = ++k.seq;
    b.tick = game_->tick();
    b.num_slots = static_cast<int>(k.slots.size());
    b.slots = k.slots;
    b.obs_size = game_->obs_size();
    b.num_terms = static_cast<int>(game_->reward_terms().size());
    b.term_names = game_->reward_terms();
    for (int s : k.slots) {
      std::vector<float> obs(b.obs_size);
      game_->observe(s, obs);
      b.obs.push_back(std::move(obs));
      b.reward.push_back(out.reward[s]);
      b.terms.push_back(out.terms[s]);
      b.done.push_back(out.done[s] != 0);
      b.truncated.push_back(out.truncated[s] != 0);
    }
    b.info = info_text;
    if (k.bundled) {
      const auto bytes = protocol::encode(b);
      if (log_) log_->write(description_.obs_channel, bytes.data(), static_cast<int>(bytes.size()));
      outbox_->add(k.id, identity_.match_id, bytes);
    } else {
      send(description_.obs_channel, b);
    }
    if (out.match_over) final_batches_[k.id] = std::move(b);
  }
}

void MatchRuntime::forfeit(int client, const std::string& why, Clock::time_point now) {
  const Client& k = clients_[client];
  const int team = game_->team_of(k.slots.front());
  const std::string reason =
      "forfeit: agent \"" + k.agent + "\" (team " + std::to_string(team) + ") " + why;
  std::fprintf(stderr, "[%s] %s\n", identity_.match_id.c_str(), reason.c_str());
  forfeit_ = nlohmann::json{{"tick", game_->tick()}, {"team", team}, {"reason", reason}};
  if (phase_ == Phase::Running) begin_scene();
  game_->forfeit(team, reason);
  if (scene_started_) record([&](SceneRecorder& r) { r.tick(*game_); });
  publish_observations(all_clients());
  finish(now);
}

void MatchRuntime::finish(Clock::time_point now) {
  phase_ = Phase::Finished;
  finished_ = true;
  finished_at_unix_ = std::chrono::duration_cast<std::chrono::seconds>(
                          std::chrono::system_clock::now().time_since_epoch())
                          .count();
  const auto& out = game_->outcome();
  auto& r = result_;
  r.protocol_version = protocol::kProtocolVersion;
  r.match_id = identity_.match_id;
  r.server_id = identity_.server_id;
  r.server_version = protocol::kSoftwareVersion;
  r.sport = identity_.sport;
  r.mode = identity_.settings.mode;
  r.seed = static_cast<std::int64_t>(identity_.settings.seed);
  r.ticks = game_->tick();
  // A match cancelled before it started has no duration.
  r.duration_s = started_at_ != Clock::time_point{}
                     ? static_cast<float>(Seconds(now - started_at_).count())
                     : 0.0f;
  r.reason = out.reason;
  r.winner_team = out.winner_team;
  r.num_teams = game_->team_count();
  r.scores = out.scores;
  r.num_slots = game_->slot_count();
  r.slot_team = description_.slot_team;
  for (int s = 0; s < r.num_slots; ++s) {
    const Client* k = slot_owner_[s] >= 0 ? &clients_[slot_owner_[s]] : nullptr;
    r.agent_names.push_back(k ? k->agent : "");
    r.policy_ids.push_back(k ? k->policy : "");
    r.policy_versions.push_back(k ? k->policy_version : "");
  }
  r.info = out.info.dump();
  r.options = identity_.settings.options.dump();
  record([&](SceneRecorder& rec) { rec.finish(*game_); });
  // The host stores the result first and then publishes it (publish_result), so whoever hears
  // the result can read it from the store.
}

void MatchRuntime::publish_result() {
  // Whoever hears the result may read the match's LCM log at once: it is whole on disk first.
  send(protocol::kResult, result_, /*log_whole=*/true);
}

std::vector<StoredParticipant> MatchRuntime::participants() const {
  std::vector<StoredParticipant> out;
  for (int s = 0; s < game_->slot_count(); ++s) {
    const Client* k = slot_owner_[s] >= 0 ? &clients_[slot_owner_[s]] : nullptr;
    out.push_back(
        {s, game_->team_of(s), k ? k->agent : "", k ? k->policy : "", k ? k->policy_version : ""});
  }
  return out;
}

bool MatchRuntime::take_started() {
  if (phase_ == Phase::Joining || start_reported_) return false;
  start_reported_ = true;
  return true;
}

std::vector<std::string> MatchRuntime::client_ids() const {
  std::vector<std::string> ids;
  for (const auto& c : clients_) ids.push_back(c.id);
  return ids;
}

StoredMatch MatchRuntime::stored_result() const {
  StoredMatch m;
  const auto& r = result_;
  m.match_id = r.match_id, m.server_id = r.server_id, m.server_version = r.server_version;
  m.sport = r.sport, m.mode = r.mode, m.seed = r.seed, m.realtime = identity_.realtime;
  m.ticks = r.ticks, m.wall_time_s = r.duration_s, m.reason = r.reason,
  m.winner_team = r.winner_team;
  m.scores.assign(r.scores.begin(), r.scores.end());
  m.info = r.info;
  m.options = r.options;
  m.finished_at_unix = finished_at_unix_;
  for (int s = 0; s < r.num_slots; ++s)
    m.participants.push_back(
        {s, r.slot_team[s], r.agent_names[s], r.policy_ids[s], r.policy_versions[s]});
  return m;
}

Replay MatchRuntime::replay() const {
  Replay rp;
  rp.slot_count = game_->slot_count();
  rp.action_size = game_->action_size();
  rp.actions = replay_actions_;
  const auto& r = result_;
  std::vector<double> scores(r.scores.begin(), r.scores.end());
  rp.header = identity_header(r.agent_names);
  rp.header["result"] = {{"ticks", r.ticks},
                         {"reason", r.reason},
                         {"winner_team", r.winner_team},
                         {"scores", scores},
                         {"state_hash", game_->state_hash()}};
  if (forfeit_) rp.header["forfeit"] = *forfeit_;
  return rp;
}

}  // namespace olympics::server
