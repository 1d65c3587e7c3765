#include "vector_client.h"

#include <algorithm>
#include <map>

#include "bundle.h"
#include "channels.h"

namespace olympics::client {
namespace {
constexpr double kResendS = 0.25;         // requests and joins, until answered
constexpr double kResultWaitS = 30;       // how long an ended match is kept to hear its result
constexpr double kMaintainEveryS = 0.02;  // heartbeats, resends, checks for lost matches
}  // namespace

struct VectorClient::Env {
  enum class Phase { kAwaitingAssignment, kRequesting, kJoining, kPlaying };
  int index = 0;
  int episode = -1;
  Phase phase = Phase::kRequesting;
  olympics::match_request_t request;
  std::string match_id;
  std::vector<int> slots;  // joined in its match
  Connection::Clock::time_point next_send, last_progress;
  std::unique_ptr<MatchSession> session;
  bool waiting = false;              // its next observation is owed to the caller
  int tick = -1;                     // of the observation handed out last
  std::optional<Observation> ready;  // the next observation, once here
  std::optional<Observation> final;  // the ended match's last one, when it just ended
  std::optional<Observation> last;   // the last one handed out
};

VectorClient::VectorClient(const ClientOptions& options, VectorSettings settings)
    : connection_(options), settings_(std::move(settings)), slots_(settings_.slots) {
  if (settings_.num_envs < 1) throw std::invalid_argument("num_envs must be at least 1");
  if (settings_.request_prefix.empty()) settings_.request_prefix = connection_.client_id();
  std::sort(slots_.begin(), slots_.end());
  for (int e = 0; e < settings_.num_envs; ++e) {
    envs_.push_back(std::make_unique<Env>());
    envs_.back()->index = e;
  }
}

VectorClient::~VectorClient() = default;

const olympics::match_created_t& VectorClient::match(int env) const {
  static const olympics::match_created_t none{};
  const auto& s = envs_.at(env)->session;
  return s ? s->match() : none;
}

void VectorClient::start_next_match(Env& env) {
  ++env.episode;
  MatchRequest r = settings_.request;
  r.seed = settings_.request.seed + static_cast<std::int64_t>(env.episode) * settings_.num_envs +
           env.index;
  const std::string id = settings_.request_prefix + "-" + std::to_string(env.index) + "-" +
                         std::to_string(env.episode);
  env.request = Connection::request_message(r, id);
  env.session.reset();
  env.ready.reset();
  env.last.reset();
  env.tick = -1;
  env.last_progress = Connection::Clock::now();
  if (!settings_.learner.empty()) {
    env.phase = Env::Phase::kAwaitingAssignment;
    return;
  }
  env.phase = Env::Phase::kRequesting;
  connection_.send_request(env.request);
  env.next_send = Connection::Clock::now() + seconds(kResendS);
}

// Moves one environment along: request answered → join; join accepted → play; observation in.
// `maintain`: also heartbeats, resends and the checks for a lost match, which need not run at
// every message that comes in (they are due every kMaintainEveryS).
void VectorClient::advance(Env& env, Connection::Clock::time_point now, bool maintain) {
  // The common case, cheaply: a match under way with nothing new (recv calls this for every
  // waiting environment at every message that comes in).
  if (env.phase == Env::Phase::kPlaying && !maintain &&
      (env.ready || !env.session->has_observation()))
    return;
  const auto where = [&] {
    return "environment " + std::to_string(env.index) + " (request " + env.request.request_id +
           "): ";
  };
  if (env.phase == Env::Phase::kAwaitingAssignment) {
    env.last_progress = now;  // waiting for the league is not the match's silence
    if (auto a = connection_.take_assignment(settings_.learner)) {
      if (!slots_.empty() && a->slots.size() != slots_.size())
        throw MatchError("BAD_REQUEST", where() + "the league assigned " +
                                            std::to_string(a->slots.size()) + " slots, not " +
                                            std::to_string(slots_.size()));
      if (slots_.empty()) slots_ = a->slots;
      env.match_id = a->match_id;
      env.slots = a->slots;
      std::sort(env.slots.begin(), env.slots.end());
      env.phase = Env::Phase::kJoining;
      connection_.send_join(env.match_id, env.slots);
      env.next_send = now + seconds(kResendS);
    }
  }
  if (env.phase == Env::Phase::kRequesting) {
    if (auto created = connection_.take_created(env.request.request_id)) {
      env.match_id = created->match_id;
      if (slots_.empty())
        for (int s = 0; s < created->num_slots; ++s) slots_.push_back(s);
      env.slots = slots_;
      env.phase = Env::Phase::kJoining;
      connection_.send_join(env.match_id, env.slots);
      env.next_send = now + seconds(kResendS);
      env.last_progress = now;
    } else if (auto e = connection_.take_request_error(env.request.request_id)) {
      // A full server has room again when a match ends: ask again later. Anything else is
      // a request that can never succeed.
      if (e->code != "FULL") throw MatchError(e->code, where() + e->message);
    } else if (now >= env.next_send) {
      connection_.send_request(env.request);
      env.next_send = now + seconds(kResendS);
    }
  }
  if (env.phase == Env::Phase::kJoining) {
    if (auto reply = connection_.take_join_reply(env.match_id)) {
      if (!reply->accepted) throw MatchError("REFUSED", where() + reply->reason);
      if (obs_size_ == 0)
        obs_size_ = reply->match.obs_size, action_size_ = reply->match.action_size;
      if (reply->match.obs_size != obs_size_ || reply->match.action_size != action_size_)
        throw MatchError("BAD_REQUEST", where() +
                                            "its match has other vector sizes than the "
                                            "first one's");
      env.session = std::make_unique<MatchSession>(connection_, reply->match, env.slots);
      env.phase = Env::Phase::kPlaying;
      env.last_progress = now;
    } else if (auto e = connection_.fatal_error(env.match_id, /*joining=*/true)) {
      throw MatchError(e->code, where() + e->message);
    } else if (now >= env.next_send) {
      connection_.send_join(env.match_id, env.slots);
      env.next_send = now + seconds(kResendS);
    }
  }
  if (env.phase == Env::Phase::kPlaying && !env.ready) {
    if (maintain) env.session->maintain();
    auto o = env.session->take_observation();
    if (!o && maintain && env.last && env.session->ended_without_final_observation()) {
      // Over, and its final observation lost for good: the last one we saw, every slot done,
      // nothing earned.
      o = env.last;
      o->tick += 1;
      std::fill(o->reward.begin(), o->reward.end(), 0.0f);
      for (auto& row : o->terms) std::fill(row.begin(), row.end(), 0.0f);
      std::fill(o->done.begin(), o->done.end(), true);
    }
    if (o) {
      env.last_progress = now;
      if (term_names_.empty()) term_names_ = o->term_names;
      if (o->all_done()) {  // this client's part of the match is over: on to the next one
        env.final = std::move(o);
        ending_.push_back({std::move(env.session), now});
        start_next_match(env);
      } else {
        env.ready = std::move(o);
      }
    }
  }
  if (now - env.last_progress > seconds(settings_.timeout_s))
    throw MatchError("TIMEOUT", where() + "nothing from its match for " +
                                    std::to_string(settings_.timeout_s) + " s" +
                                    connection_.silence_hint());
}

void VectorClient::collect_results() {
  const auto now = Connection::Clock::now();
  std::erase_if(ending_, [&](Ending& ending) {
    if (const auto* r = ending.session->result()) {
      results_.push_back(*r);
      return true;
    }
    try {
      ending.session->maintain();  // resends the last action: a finished server answers it
    } catch (const MatchError&) {  // with the result
      return true;                 // lost: the results store has it, if anything
    }
    return now - ending.since > seconds(kResultWaitS);
  });
}

// Row `row` of a batch sized for its environments: the environment's ready observation (and,
// when its match just ended, that match's last one with its reward and flags; zeros where
// there is none).
void VectorClient::fill(VectorBatch& b, size_t row, Env& env) {
  const Observation& now = *env.ready;
  // The reward and flags of an ended match are its last tick's; the observation is the next
  // match's first.
  const Observation& scored = env.final ? *env.final : now;
  const size_t agents = slots_.size(), terms = term_names_.size(), obs = obs_size_;
  b.envs[row] = env.index;
  b.tick[row] = now.tick;
  b.episode_over[row] = env.final ? 1 : 0;
  for (size_t a = 0; a < agents; ++a) {
    const size_t at = row * agents + a;
    std::copy(now.obs[a].begin(), now.obs[a].end(), b.obs.begin() + at * obs);
    const auto final_row = b.final_obs.begin() + at * obs;
    if (env.final)
      std::copy(env.final->obs[a].begin(), env.final->obs[a].end(), final_row);
    else
      std::fill(final_row, final_row + obs, 0.0f);
    b.reward[at] = scored.reward[a];
    for (size_t t = 0; t < terms; ++t)
      b.terms[at * terms + t] = t < scored.terms[a].size() ? scored.terms[a][t] : 0.0f;
    b.truncated[at] = scored.truncated[a] ? 1 : 0;
    b.terminated[at] = scored.done[a] && !scored.truncated[a] ? 1 : 0;
  }
  env.tick = now.tick;
  env.last = std::move(env.ready);
  env.ready.reset();
  env.final.reset();
  env.waiting = false;
}

// Every environment whose next observation is here, as one batch. The arrays are the client's
// own, sized anew each time but allocated once: a step of 256 sandbox matches is 1.5 MB, and
// fresh arrays cost more in page faults and zeroing than the copying itself.
const VectorBatch& VectorClient::take_ready() {
  std::vector<Env*> ready;
  for (auto& env : envs_)
    if (env->waiting && env->ready) ready.push_back(env.get());
  const size_t n = ready.size(), rows = n * slots_.size();
  VectorBatch& b = batch_;
  b.envs.resize(n);
  b.tick.resize(n);
  b.episode_over.resize(n);
  b.obs.resize(rows * obs_size_);
  b.final_obs.resize(rows * obs_size_);
  b.reward.resize(rows);
  b.terms.resize(rows * term_names_.size());
  b.terminated.resize(rows);
  b.truncated.resize(rows);
  for (size_t i = 0; i < n; ++i) fill(b, i, *ready[i]);
  return b;
}

void VectorClient::start() {
  for (auto& env : envs_) {
    start_next_match(*env);
    env->final.reset();
    env->waiting = true;
  }
}

const VectorBatch& VectorClient::reset() {
  start();
  return recv(num_envs());
}

const VectorBatch& VectorClient::step(std::span<const float> actions) {
  std::vector<int> all(envs_.size());
  for (size_t e = 0; e < all.size(); ++e) all[e] = static_cast<int>(e);
  send(all, actions);
  return recv(num_envs());
}

void VectorClient::send(std::span<const int> envs, std::span<const float> actions) {
  const size_t agents = slots_.size(), row = static_cast<size_t>(action_size_);
  if (actions.size() != envs.size() * agents * row)
    throw MatchError("BAD_ACTION", "send() got " + std::to_string(actions.size()) + " floats for " +
                                       std::to_string(envs.size()) + " environments x " +
                                       std::to_string(agents) + " agents x " + std::to_string(row) +
                                       " actions");
  for (size_t i = 0; i < envs.size(); ++i) {
    const Env& env = *envs_.at(envs[i]);
    if (env.waiting || env.phase != Env::Phase::kPlaying)
      throw MatchError("NOT_READY", "environment " + std::to_string(envs[i]) +
                                        " has not returned its observation since its last send");
  }
  // One bundle (or as few as fit a datagram) per server for all of these matches' actions;
  // the server then answers each of its workers' share with one bundle too.
  std::map<std::string, protocol::BundleWriter> by_server;
  for (size_t i = 0; i < envs.size(); ++i) {
    Env& env = *envs_.at(envs[i]);
    std::vector<std::vector<float>> rows(agents);
    for (size_t a = 0; a < agents; ++a) {
      const float* at = actions.data() + (i * agents + a) * row;
      rows[a].assign(at, at + row);
    }
    const auto& match = env.session->match();
    by_server.try_emplace(match.server_id, connection_.client_id())
        .first->second.add(match.match_id, env.session->prepare_action(env.tick, rows));
    env.waiting = true;
    env.last_progress = Connection::Clock::now();
  }
  for (auto& [server_id, writer] : by_server) {
    const std::string channel = protocol::action_bundle_channel(server_id);
    for (const auto& bundle : writer.take())
      connection_.transport().publish_raw(channel, bundle.data(), static_cast<int>(bundle.size()));
  }
}

const VectorBatch& VectorClient::recv(int min_ready, double timeout_s) {
  int waiting = 0;
  for (const auto& env : envs_) waiting += env->waiting ? 1 : 0;
  min_ready = std::clamp(min_ready, 0, waiting);
  auto next_maintenance = Connection::Clock::now();
  const auto give_up =
      timeout_s < 0 ? Connection::Clock::time_point::max() : next_maintenance + seconds(timeout_s);
  for (;;) {
    connection_.drain();
    const auto now = Connection::Clock::now();
    const bool maintain = now >= next_maintenance;
    int ready = 0;
    for (auto& env : envs_)
      if (env->waiting) {
        advance(*env, now, maintain);
        ready += env->ready ? 1 : 0;
      }
    if (ready >= min_ready || Connection::Clock::now() >= give_up) return take_ready();
    if (maintain) {
      for (auto& env : envs_)
        if (!env->waiting && env->session) env->session->maintain();
      collect_results();
      next_maintenance = now + seconds(kMaintainEveryS);
    }
    connection_.pump(now + std::chrono::milliseconds(10));
  }
}

std::vector<olympics::match_result_t> VectorClient::take_results() {
  connection_.drain();
  collect_results();
  std::vector<olympics::match_result_t> out;
  out.swap(results_);
  return out;
}

}  // namespace olympics::client
