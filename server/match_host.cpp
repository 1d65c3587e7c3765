#include "match_host.h"

#include <pthread.h>
#include <time.h>

#include <cstdio>
#include <filesystem>

#include "bundle.h"
#include "channels.h"
#include "match_id.h"
#include "olympics/action_batch_t.hpp"
#include "olympics/error_t.hpp"
#include "olympics/heartbeat_t.hpp"
#include "olympics/join_t.hpp"
#include "olympics/match_request_t.hpp"
#include "olympics/server_announce_t.hpp"
#include "registry.h"
#include "version.h"

namespace olympics::server {
namespace {
constexpr size_t kRememberedResults = 1000;
// How long a finished match's request id is remembered: well past the age at which any datagram
// of that request is stale (protocol::kMaxMessageAgeMs), so a replay of it can make no match.
constexpr double kRequestMemoryS = 6.0 * protocol::kMaxMessageAgeMs / 1000;
// A sender asking about a finished match is told its end at most this often.
constexpr double kRetellS = 0.2;

constexpr double kPeerTimeoutS = 3.0;
}  // namespace

MatchHost::MatchHost(HostSettings settings, protocol::Transport& transport, ResultsStore& store)
    : settings_(std::move(settings)),
      transport_(transport),
      store_(store),
      boot_us_(std::chrono::duration_cast<std::chrono::microseconds>(
                   std::chrono::system_clock::now().time_since_epoch())
                   .count()),
      boot_tag_(protocol::boot_tag(boot_us_)) {
  int n = settings_.workers > 0
              ? settings_.workers
              : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  if (!settings_.replay_dir.empty()) std::filesystem::create_directories(settings_.replay_dir);
  for (int i = 0; i < n; ++i) workers_.push_back(std::make_unique<Worker>());
  for (auto& w : workers_) w->thread = std::thread([this, raw = w.get()] { worker_loop(*raw); });
}

MatchHost::~MatchHost() {
  stopping_ = true;
  for (auto& w : workers_) {
    { std::lock_guard lock(w->mutex); }
    w->wake.notify_all();
    w->thread.join();
  }
}

double MatchHost::worker_cpu_seconds() const {
  double total = 0;
  for (const auto& w : workers_) {
    clockid_t clock;
    timespec t{};
    if (pthread_getcpuclockid(const_cast<std::thread&>(w->thread).native_handle(), &clock) == 0 &&
        clock_gettime(clock, &t) == 0)
      total += t.tv_sec + t.tv_nsec * 1e-9;
  }
  return total;
}

int MatchHost::active_matches() const { return playing_; }

namespace {
// `e` with its message cut so that it encodes to at most `limit` bytes; nullopt when even an
// empty message is too long.
std::optional<olympics::error_t> fitted(olympics::error_t e, int limit) {
  const int over = e.getEncodedSize() - limit;
  if (over <= 0) return e;
  if (over > static_cast<int>(e.message.size())) return std::nullopt;
  e.message.resize(e.message.size() - over);
  return e;
}
}  // namespace

void MatchHost::log_error(const std::string& code, const std::string& message) {
  protocol::LogThrottle* throttle;
  {
    std::lock_guard lock(error_logs_mutex_);
    auto& t = error_logs_[code];
    if (!t) t = std::make_unique<protocol::LogThrottle>();
    throttle = t.get();
  }
  if (const long n = throttle->note())
    std::fprintf(
        stderr, "[server %s] %s: %s%s\n", settings_.server_id.c_str(), code.c_str(),
        message.c_str(),
        n > 1 ? (" (and " + std::to_string(n - 1) + " more in the last second)").c_str() : "");
}

void MatchHost::error(const std::string& match_id, const std::string& client_id,
                      const std::string& code, const std::string& message, int answered_bytes) {
  if ((code == "MALFORMED" || code == "UNKNOWN_MATCH") && !transport_.may_complain()) return;
  olympics::error_t e;
  e.protocol_version = protocol::kProtocolVersion;
  e.server_id = settings_.server_id;
  e.match_id = match_id;
  e.client_id = client_id;
  e.code = code;
  e.message = message;
  log_error(code, message);
  if (answered_bytes <= 0) return transport_.publish(protocol::kError, e);
  if (auto cut = fitted(std::move(e), answered_bytes)) transport_.publish(protocol::kError, *cut);
}

void MatchHost::hint(const std::string& code, const std::string& message, int answered_bytes) {
  log_error(code, message);
  if (!transport_.may_complain()) return;
  olympics::error_t e;
  e.protocol_version = protocol::kProtocolVersion;
  e.code = code;
  e.message = message;
  if (auto cut = fitted(std::move(e), answered_bytes))
    transport_.publish_unsigned(protocol::kError, *cut);
}

void MatchHost::run(const std::atomic<bool>& stop) {
  // What an earlier run under this id left unfinished (a crash) is recorded as aborted.
  try {
    const auto now = std::chrono::duration_cast<std::chrono::seconds>(
                         std::chrono::system_clock::now().time_since_epoch())
                         .count();
    if (int n = store_.abort_unfinished(settings_.server_id, now); n > 0) {
      std::printf("recorded %d match(es) an earlier run of %s left unfinished as aborted\n", n,
                  settings_.server_id.c_str());
      std::fflush(stdout);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "[server %s] could not record unfinished matches: %s\n",
                 settings_.server_id.c_str(), e.what());
  }
  remove_unfinished_scene_tracks();
  transport_.subscribe(protocol::kRequest, [this](const std::string&, const std::uint8_t* d,
                                                  int n) { on_request(d, n); });
  // A client whose joins or requests fail the signature check (no secret, another one, or
  // another protocol version) learns so within seconds: a hint, unsigned and naming no ids (a
  // signed answer naming them would let anyone end another client's request or join), and no
  // bigger than what it answers. Clients only report it (an outsider can send one too).
  transport_.on_unauthenticated([this](const std::string& ch, const std::uint8_t*, int n) {
    if (ch == protocol::kJoin || ch == protocol::kRequest)
      hint("UNAUTHENTICATED",
           "signature check failed: another --secret, none, or protocol != " +
               std::to_string(protocol::kProtocolVersion),
           n);
  });
  transport_.subscribe_to<olympics::server_announce_t>(
      protocol::kAnnounce,
      [this](const std::string&, const olympics::server_announce_t& a) { on_announce(a); });
  transport_.subscribe(protocol::kJoin, [this](const std::string& ch, const std::uint8_t* d,
                                               int n) {
    auto join = protocol::decode<olympics::join_t>(d, n);
    if (!join) {
      transport_.count_malformed();
      return error("", "", "MALFORMED",
                   "could not decode a join_t of " + std::to_string(n) +
                       " bytes: truncated, corrupted, or from another protocol version; upgrade "
                       "the client",
                   n);
    }
    route(join->match_id, ch, d, n, join->client_id);
  });
  transport_.subscribe(protocol::kHeartbeat,
                       [this](const std::string& ch, const std::uint8_t* d, int n) {
                         auto beat = protocol::decode<olympics::heartbeat_t>(d, n);
                         if (!beat) return transport_.count_malformed();
                         route(beat->match_id, ch, d, n, beat->client_id);
                       });
  transport_.subscribe(
      protocol::action_bundle_channel(settings_.server_id),
      [this](const std::string&, const std::uint8_t* d, int n) { on_action_bundle(d, n); });
  exact_action_channels_ = transport_.url().rfind("mpudpm://", 0) == 0;
  if (!exact_action_channels_)
    transport_.subscribe(std::string(protocol::kActPrefix) + ".*",
                         [this](const std::string& ch, const std::uint8_t* d, int n) {
                           route(ch.substr(std::string(protocol::kActPrefix).size()), ch, d, n, "");
                         });
  auto next_announce = std::chrono::steady_clock::now();
  while (!stop) {
    transport_.handle(20);
    std::vector<std::string> ended;
    {
      std::lock_guard lock(routes_mutex_);
      ended.swap(to_unsubscribe_);
    }
    for (const auto& id : ended)
      if (auto it = action_subscriptions_.find(id); it != action_subscriptions_.end()) {
        transport_.unsubscribe(it->second);
        action_subscriptions_.erase(it);
      }
    auto now = std::chrono::steady_clock::now();
    if (now >= next_announce) {
      announce();
      next_announce =
          now + std::chrono::milliseconds(static_cast<int>(settings_.announce_interval_s * 1000));
    }
  }
}

// A crash (or a kill) leaves the scene tracks of the matches it cut short as <match>.scene.part:
// never a whole track, so nothing reads them. This server's are those whose match id starts with
// its id and '-' (an id holds no '-', so no other server's id begins the same way).
void MatchHost::remove_unfinished_scene_tracks() {
  if (settings_.replay_dir.empty()) return;
  const std::string mine = settings_.server_id + "-";
  std::error_code ec;
  int removed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(settings_.replay_dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(mine, 0) == 0 && name.ends_with(".scene.part") &&
        std::filesystem::remove(entry.path(), ec))
      ++removed;
  }
  if (removed > 0) {
    std::printf("removed %d unfinished scene track(s) an earlier run of %s left\n", removed,
                settings_.server_id.c_str());
    std::fflush(stdout);
  }
}

void MatchHost::announce() {
  olympics::server_announce_t a;
  a.protocol_version = protocol::kProtocolVersion;
  a.server_id = settings_.server_id;
  a.server_version = protocol::kSoftwareVersion;
  a.timestamp_us = std::chrono::duration_cast<std::chrono::microseconds>(
                       std::chrono::system_clock::now().time_since_epoch())
                       .count();
  a.capacity = settings_.capacity;
  a.active_matches = active_matches();
  a.sports = sports::sport_names();
  a.num_sports = static_cast<int>(a.sports.size());
  a.boot_us = boot_us_;
  a.refused_malformed = transport_.malformed();
  a.refused_unauthenticated = transport_.unauthenticated();
  transport_.publish(protocol::kAnnounce, a);
}

void MatchHost::forget_old_requests() {
  const auto now = std::chrono::steady_clock::now();
  while (!finished_requests_.empty() &&
         now - finished_requests_.front().first > std::chrono::duration<double>(kRequestMemoryS)) {
    requests_.erase(finished_requests_.front().second);
    finished_requests_.pop_front();
  }
}

void MatchHost::on_announce(const olympics::server_announce_t& a) {
  if (a.server_id == settings_.server_id) return;
  std::lock_guard lock(routes_mutex_);
  // An announcement of an earlier boot than one heard (a stopped process's, replayed) says
  // nothing about the server now.
  auto& boot = peer_boots_[a.server_id];
  if (a.boot_us < boot) return;
  boot = a.boot_us;
  peers_[a.server_id] = {std::chrono::steady_clock::now(), a.capacity - a.active_matches};
}

// Several servers on one network all hear a request addressed to nobody; the one with the
// smallest id among those with room takes it, so exactly one answers.
bool MatchHost::should_take_unaddressed_request() {
  auto now = std::chrono::steady_clock::now();
  std::lock_guard lock(routes_mutex_);
  for (const auto& [id, seen] : peers_)
    if (now - seen.first < std::chrono::duration<double>(kPeerTimeoutS) && seen.second > 0 &&
        id < settings_.server_id)
      return false;
  return true;
}

void MatchHost::on_request(const std::uint8_t* data, int size) {
  auto req = protocol::decode<olympics::match_request_t>(data, size);
  if (!req) {
    transport_.count_malformed();
    return error("", "", "MALFORMED",
                 "could not decode a match_request_t of " + std::to_string(size) +
                     " bytes: truncated, corrupted, or from another protocol version",
                 size);
  }
  if (!req->server_id.empty() && req->server_id != settings_.server_id) return;
  if (req->server_id.empty() && !should_take_unaddressed_request()) return;
  // Named by its request id, so that the requesting client (of any version: error_t has not
  // changed) reports it instead of waiting for an answer.
  if (auto v = protocol::version_mismatch(req->protocol_version))
    return error("", "", "UPGRADE", "request " + req->request_id + ": " + *v);
  {
    std::lock_guard lock(routes_mutex_);
    if (auto it = requests_.find(req->request_id);
        it != requests_.end() && !req->request_id.empty()) {
      // A resent request: the same match (none yet while its worker creates it).
      if (!it->second.match_id.empty()) transport_.publish(protocol::kCreated, it->second);
      return;
    }
  }
  const sports::Sport* sport = sports::find_sport(req->sport);
  if (!sport) {
    std::string known;
    for (const auto& n : sports::sport_names()) known += (known.empty() ? "" : ", ") + n;
    return error("", "", "UNKNOWN_SPORT",
                 "request " + req->request_id + ": unknown sport \"" + req->sport +
                     "\"; known sports: " + known);
  }
  if (!(req->time_limit_s >= 0 && req->time_limit_s <= 3600))
    return error("", "", "BAD_REQUEST",
                 "request " + req->request_id + ": time_limit_s must be 0..3600");
  if (active_matches() >= settings_.capacity)
    return error("", "", "FULL",
                 "request " + req->request_id + ": server " + settings_.server_id + " hosts " +
                     std::to_string(settings_.capacity) + " matches already; try another server");

  nlohmann::json options = nlohmann::json::object();
  if (!req->options.empty()) {
    options = nlohmann::json::parse(req->options, nullptr, /*allow_exceptions=*/false);
    if (!options.is_object())
      return error("", "", "BAD_REQUEST",
                   "request " + req->request_id +
                       ": options must be a JSON object such as {\"format\": \"tiebreak\"}, "
                       "got: " +
                       req->options.substr(0, 200));
  }

  MatchIdentity id;
  id.server_id = settings_.server_id;
  id.sport = req->sport;
  id.settings = {req->mode, static_cast<std::uint64_t>(req->seed), req->time_limit_s, options};
  id.realtime = req->realtime;
  int worker;
  {
    std::lock_guard lock(routes_mutex_);
    // The boot in the id keeps ids unique across restarts under the same server id.
    id.match_id = protocol::make_match_id(settings_.server_id, boot_tag_, next_match_number_++);
    worker = next_worker_++ % static_cast<int>(workers_.size());
    routes_[id.match_id] = worker;
    if (!req->request_id.empty()) {
      requests_[req->request_id] = {};  // being created: a resend of it waits for the answer
      request_of_match_[id.match_id] = req->request_id;
    }
    ++playing_;
  }
  // Its actions may come as soon as the client hears of it: listen before the worker answers.
  if (exact_action_channels_) subscribe_actions(id.match_id);
  // The world is built, noted in the store and announced by the worker that will step it, so
  // that a wave of requests (a vector client's matches ending together) is created in parallel,
  // not one after another on this receiving thread.
  Worker& w = *workers_[worker];
  {
    std::lock_guard lock(w.mutex);
    w.to_create.push_back({std::move(id), req->request_id, sport});
  }
  w.wake.notify_one();
}

// On the match's worker: the world, its runtime and recorders; the request is answered with
// match_created_t once the match can take joins. A request the sport refuses (an unknown mode
// or setting) is answered with BAD_REQUEST and leaves nothing behind.
std::unique_ptr<MatchRuntime> MatchHost::create_match(PendingMatch pending) {
  MatchIdentity& id = pending.identity;
  std::unique_ptr<sports::SportMatch> game;
  try {
    game = pending.sport->create(id.settings);
    // What is in force, recorded with the match and its replay: the sport's time limit when
    // the request left it to the sport, every setting with its default filled in.
    id.settings.time_limit_s = game->time_limit_s();
    id.settings.options = sports::merge_settings(pending.sport->name(), pending.sport->settings(),
                                                 id.settings.options);
  } catch (const std::invalid_argument& e) {
    {
      std::lock_guard lock(routes_mutex_);
      routes_.erase(id.match_id);
      requests_.erase(pending.request_id);
      request_of_match_.erase(id.match_id);
      if (exact_action_channels_) to_unsubscribe_.push_back(id.match_id);
      --playing_;
    }
    error("", "", "BAD_REQUEST", "request " + pending.request_id + ": " + e.what());
    return nullptr;
  }
  std::unique_ptr<TrafficLog> log;
  if (settings_.lcm_logs && !settings_.replay_dir.empty())
    log = std::make_unique<TrafficLog>(settings_.replay_dir + "/" + id.match_id + ".lcmlog");
  auto runtime =
      std::make_unique<MatchRuntime>(id, id.realtime ? settings_.realtime : settings_.sync,
                                     std::move(game), transport_, std::move(log));
  const bool scene_file = settings_.scene_tracks && !settings_.replay_dir.empty();
  if (scene_file || settings_.live)
    runtime->record_scene(std::make_unique<SceneRecorder>(
        scene_file ? settings_.replay_dir + "/" + id.match_id + ".scene" : "",
        settings_.live ? settings_.live->add(id.match_id, {{"match_id", id.match_id},
                                                           {"sport", id.sport},
                                                           {"mode", id.settings.mode},
                                                           {"seed", id.settings.seed}})
                       : nullptr));
  note_in_progress(*runtime, id);
  return runtime;
}

// The answer to a match's request, once its worker holds it.
void MatchHost::announce_created(const MatchRuntime& match, const std::string& request_id) {
  olympics::match_created_t created = match.description();
  created.request_id = request_id;
  {
    std::lock_guard lock(routes_mutex_);
    if (auto it = requests_.find(request_id); it != requests_.end()) it->second = created;
  }
  transport_.publish(protocol::kCreated, created);
}

void MatchHost::subscribe_actions(const std::string& match_id) {
  action_subscriptions_[match_id] =
      transport_.subscribe(protocol::action_channel(match_id),
                           [this, match_id](const std::string& ch, const std::uint8_t* d, int n) {
                             route(match_id, ch, d, n, "");
                           });
}

void MatchHost::note_in_progress(const MatchRuntime& runtime, const MatchIdentity& id) {
  StoredMatch m;
  m.match_id = id.match_id, m.server_id = id.server_id, m.sport = id.sport;
  m.mode = id.settings.mode, m.seed = static_cast<std::int64_t>(id.settings.seed);
  m.realtime = id.realtime, m.options = id.settings.options.dump();
  m.finished_at_unix = std::chrono::duration_cast<std::chrono::seconds>(
                           std::chrono::system_clock::now().time_since_epoch())
                           .count();
  m.participants = runtime.participants();
  writes_.post([this, m] {
    try {
      store_.note_in_progress(m);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "[%s] could not note the match as in progress: %s\n", m.match_id.c_str(),
                   e.what());
    }
  });
}

// Who sent a routed message: the client id its join or heartbeat carried, or an action batch's.
std::string MatchHost::sender(const std::string& client_id, const std::uint8_t* data, int size) {
  if (!client_id.empty()) return client_id;
  auto batch = protocol::decode<olympics::action_batch_t>(data, size);
  return batch ? batch->client_id : "";
}

// A vector client's actions for its matches here: each part goes where it would have gone alone.
void MatchHost::on_action_bundle(const std::uint8_t* data, int size) {
  auto bundle = protocol::decode<olympics::bundle_t>(data, size);
  std::vector<bool> woken(workers_.size(), false);
  if (bundle && protocol::for_each_part(*bundle, [&](const std::string& match_id,
                                                     const std::uint8_t* part, int part_size) {
        const int worker =
            route(match_id, protocol::action_channel(match_id), part, part_size, "", true);
        if (worker >= 0) woken[worker] = true;
      })) {
    // Each worker once, with all of its matches' actions in its inboxes: it steps them in one
    // pass and answers with one bundle.
    for (size_t w = 0; w < workers_.size(); ++w)
      if (woken[w]) workers_[w]->wake.notify_one();
    return;
  }
  transport_.count_malformed();
  error("", bundle ? bundle->client_id : "", "MALFORMED",
        "could not decode a bundle_t of " + std::to_string(size) +
            " bytes: truncated, corrupted, parts that do not add up, or from another protocol "
            "version; upgrade the client to protocol " +
            std::to_string(protocol::kProtocolVersion),
        size);
}

int MatchHost::route(const std::string& match_id, const std::string& channel,
                     const std::uint8_t* data, int size, const std::string& client_id,
                     bool bundled) {
  int worker = -1;
  {
    std::lock_guard lock(routes_mutex_);
    if (auto it = routes_.find(match_id); it != routes_.end())
      worker = it->second;
    else if (auto f = finished_.find(match_id); f != finished_.end()) {
      // Whoever still asks missed the end: its last observation batch again, then the result;
      // at most every kRetellS per sender, however often it asks.
      const std::string from = sender(client_id, data, size);
      const auto now = std::chrono::steady_clock::now();
      auto [told, first] = f->second.told.try_emplace(from, now);
      if (!first && now - told->second < std::chrono::duration<double>(kRetellS)) return -1;
      told->second = now;
      if (auto b = f->second.final_batches.find(from); b != f->second.final_batches.end())
        transport_.publish(f->second.obs_channel, b->second);
      transport_.publish(protocol::kResult, f->second.result);
      return -1;
    }
  }
  if (worker < 0) {
    // Another server's match on a shared network is not ours to refuse.
    if (match_id.rfind(settings_.server_id + "-", 0) != 0) return -1;
    // Ours, but not (or no longer) here: a match of an earlier run of this server. Its client
    // learns so at once (its id addresses the error), and gives up.
    error(match_id, sender(client_id, data, size), "UNKNOWN_MATCH",
          "no match \"" + match_id + "\" on server " + settings_.server_id + "; request one on " +
              protocol::kRequest + " and use the match_id it returns");
    return -1;
  }
  Worker& w = *workers_[worker];
  {
    std::lock_guard lock(w.mutex);
    auto it = w.entries.find(match_id);
    if (it == w.entries.end()) return -1;  // finishing right now
    it->second.inbox.push_back({channel, std::vector<std::uint8_t>(data, data + size), bundled});
  }
  if (!bundled) w.wake.notify_one();  // a bundle's workers are woken once it is all routed
  return worker;
}

void MatchHost::worker_loop(Worker& w) {
  using Clock = MatchRuntime::Clock;
  while (!stopping_) {
    std::deque<PendingMatch> to_create;
    std::vector<std::shared_ptr<MatchRuntime>> retired;
    {
      std::lock_guard lock(w.mutex);
      to_create.swap(w.to_create);
      retired.swap(w.retired);
    }
    retired.clear();  // matches whose results are stored: their worlds end on their own thread
    std::vector<std::pair<std::unique_ptr<MatchRuntime>, std::string>> created;
    for (auto& pending : to_create) {
      std::string request_id = pending.request_id;
      if (auto match = create_match(std::move(pending))) {
        match->set_outbox(&w.outbox);
        created.emplace_back(std::move(match), std::move(request_id));
      }
    }
    std::vector<std::pair<MatchRuntime*, std::deque<Inbound>>> work;
    std::vector<std::pair<const MatchRuntime*, std::string>> to_announce;
    {
      std::lock_guard lock(w.mutex);
      for (auto& [match, request_id] : created) {
        to_announce.emplace_back(match.get(), request_id);
        const std::string match_id = match->match_id();
        w.entries[match_id].match = std::move(match);
      }
      for (auto& [id, entry] : w.entries)
        work.emplace_back(entry.match.get(), std::move(entry.inbox)), entry.inbox.clear();
    }
    // Announced once routable, so that the joins answering it find the match. (Only this
    // thread erases entries: the pointers stay valid.)
    for (const auto& [match, request_id] : to_announce) announce_created(*match, request_id);
    auto next = Clock::now() + std::chrono::milliseconds(100);
    std::vector<std::string> done;
    for (auto& [match, inbox] : work) {
      for (auto& msg : inbox) match->handle(msg.channel, msg.bytes, Clock::now(), msg.bundled);
      if (match->take_started()) note_players(*match);
      next = std::min(next, match->poll(Clock::now()));
      if (match->finished()) {
        --playing_;  // its place is free before its players hear the end
        done.push_back(match->match_id());
      }
    }
    // Final observations go out before the results, which the write queue publishes once stored.
    w.outbox.flush(transport_);  // one bundle per bundling client for this whole pass
    std::unique_lock lock(w.mutex);
    for (const auto& id : done) {
      auto entry = w.entries.find(id);
      retire(w, std::move(entry->second.match));
      w.entries.erase(entry);
    }
    w.wake.wait_until(lock, next, [&] {
      if (stopping_ || !w.to_create.empty()) return true;
      for (auto& [id, entry] : w.entries)
        if (!entry.inbox.empty()) return true;
      return false;
    });
  }
}

void MatchHost::note_players(const MatchRuntime& match) {
  writes_.post([this, id = match.match_id(), players = match.participants()] {
    try {
      store_.note_players(id, players);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "[%s] could not note the players: %s\n", id.c_str(), e.what());
    }
  });
}

// A finished match leaves its worker: its result is stored, its replay written and its result
// published on the write queue, then it goes back to its worker to be destroyed there (its
// ODE world was made on that thread).
void MatchHost::retire(Worker& w, std::unique_ptr<MatchRuntime> finished) {
  writes_.post([this, &w, match = std::shared_ptr<MatchRuntime>(std::move(finished))]() mutable {
    on_finished(*match);
    std::lock_guard lock(w.mutex);
    w.retired.push_back(std::move(match));
  });
}

void MatchHost::on_finished(MatchRuntime& match) {
  try {
    store_.record(match.stored_result());
  } catch (const std::exception& e) {
    // The agents hear it (and exit with it) before the result, which they still get.
    for (const auto& client : match.client_ids())
      error(match.match_id(), client, "STORE_FAILED",
            "the result of match " + match.match_id() + " could not be stored in " +
                store_.describe() + ": " + e.what());
  }
  if (!settings_.replay_dir.empty()) {
    try {
      write_replay(settings_.replay_dir + "/" + match.match_id() + ".replay", match.replay());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "[%s] %s\n", match.match_id().c_str(), e.what());
    }
  }
  match.publish_result();
  const auto& r = match.result();
  if (settings_.log_finished) {
    std::printf("[%s] %s %s finished after %d ticks: %s, winner team %d\n", r.match_id.c_str(),
                r.sport.c_str(), r.mode.c_str(), r.ticks, r.reason.c_str(), r.winner_team);
    std::fflush(stdout);
  }
  std::lock_guard lock(routes_mutex_);
  routes_.erase(match.match_id());
  finished_[match.match_id()] = {r, match.description().obs_channel, match.final_batches(), {}};
  finished_order_.push_back(match.match_id());
  if (finished_order_.size() > kRememberedResults) {
    finished_.erase(finished_order_.front());
    if (exact_action_channels_) to_unsubscribe_.push_back(finished_order_.front());
    finished_order_.pop_front();
  }
  if (auto it = request_of_match_.find(match.match_id()); it != request_of_match_.end()) {
    finished_requests_.emplace_back(std::chrono::steady_clock::now(), it->second);
    request_of_match_.erase(it);
  }
  forget_old_requests();
  ++finished_count_;
}

}  // namespace olympics::server
