#include "tournament_runner.h"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "channels.h"
#include "match_id.h"
#include "olympics/error_t.hpp"
#include "olympics/heartbeat_t.hpp"
#include "olympics/league_assignment_t.hpp"
#include "olympics/match_created_t.hpp"
#include "olympics/match_request_t.hpp"
#include "olympics/match_result_t.hpp"
#include "olympics/server_announce_t.hpp"
#include "ratings.h"
#include "version.h"

namespace olympics::selfplay {
namespace {
constexpr auto kRequestResend = std::chrono::milliseconds(250);
constexpr auto kProbeInterval = std::chrono::seconds(1);
// Servers announce themselves once a second (MatchHost's announce_interval_s): before its first
// game a run listens this long, so that its first games spread over every server rather than
// all going to the first one heard.
constexpr auto kFirstListen = std::chrono::milliseconds(1200);
// How long an agent waits on a silent server before it gives up. A live learner's matches stand
// still while its trainer updates the policy (minutes with a large network on a CPU), so its
// opponents wait as long as the trainer's client does.
constexpr const char* kAgentTimeoutS = "60";
constexpr const char* kAgentTimeoutWithLiveLearnerS = "600";
}  // namespace

std::vector<int> team_slots(const std::vector<int>& slot_teams, int team) {
  std::vector<int> slots;
  for (size_t s = 0; s < slot_teams.size(); ++s)
    if (slot_teams[s] == team) slots.push_back(static_cast<int>(s));
  return slots;
}

std::vector<int> ranked_places(const std::string& info, int teams, int winner_team) {
  const auto j = nlohmann::json::parse(info, nullptr, false);
  if (j.is_object() && j.contains("places") && j["places"].is_array() &&
      static_cast<int>(j["places"].size()) == teams) {
    std::vector<int> places;
    for (const auto& p : j["places"])
      if (p.is_number_integer() && p.get<int>() >= 1) places.push_back(p.get<int>());
    if (static_cast<int>(places.size()) == teams) return places;
  }
  // No ranking of every team: the winner first and the rest tied behind, or all tied.
  std::vector<int> places(teams, winner_team >= 0 && winner_team < teams ? 2 : 1);
  if (winner_team >= 0 && winner_team < teams) places[winner_team] = 1;
  return places;
}

namespace {
// {2, 3} -> "2,3", as olympics-agent --slots takes them.
std::string slots_argument(const std::vector<int>& slots) {
  std::string text;
  for (int s : slots) {
    if (!text.empty()) text += ',';
    text += std::to_string(s);
  }
  return text;
}
}  // namespace

TournamentRunner::TournamentRunner(LeagueStore& store, TournamentSpec spec, RunnerSettings settings,
                                   std::unique_ptr<Scheduler> scheduler)
    : scheduler_(std::move(scheduler)),
      store_(store),
      spec_(std::move(spec)),
      settings_(std::move(settings)),
      transport_({settings_.lcm_url, 0.0, 1, protocol::load_secret(settings_.secret_file)}) {
  transport_.subscribe_to<olympics::server_announce_t>(
      protocol::kAnnounce,
      [this](const std::string&, const olympics::server_announce_t& a) { on_announce(a); });
  transport_.subscribe_to<olympics::match_created_t>(
      protocol::kCreated,
      [this](const std::string&, const olympics::match_created_t& c) { on_created(c); });
  transport_.subscribe_to<olympics::match_result_t>(
      protocol::kResult,
      [this](const std::string&, const olympics::match_result_t& r) { on_result(r); });
  transport_.subscribe_to<olympics::error_t>(
      protocol::kError, [this](const std::string&, const olympics::error_t& e) { on_error(e); });
  games_ = store_.games(spec_.name);
  // Games that were on their way when a previous run stopped: find them again (same request id,
  // which the server answers with the same match) and restart their policy workers (a slot that
  // an old worker still plays refuses the new one, which then just exits).
  for (auto& g : games_)
    if (g.status == GameStatus::Dispatched) in_flight_[g.index].dispatched = Clock::now();
}

TournamentRunner::~TournamentRunner() = default;

void TournamentRunner::save(const Game& g) { store_.update_game(spec_.name, g); }

Game* TournamentRunner::game_by_request(const std::string& request_id) {
  for (auto& g : games_)
    if (g.status == GameStatus::Dispatched && g.request_id == request_id) return &g;
  return nullptr;
}

void TournamentRunner::on_announce(const olympics::server_announce_t& announce) {
  if (!settings_.servers.empty() && std::find(settings_.servers.begin(), settings_.servers.end(),
                                              announce.server_id) == settings_.servers.end())
    return;
  if (std::find(announce.sports.begin(), announce.sports.end(), spec_.sport) ==
      announce.sports.end()) {
    std::string offered;
    for (const auto& sport : announce.sports) offered += (offered.empty() ? "" : ", ") + sport;
    other_servers_[announce.server_id] = offered;
    return;
  }
  auto& server = servers_[announce.server_id];
  const std::int64_t boot_ms = announce.boot_us / 1000;
  if (boot_ms < server.boot_ms) return;  // an earlier boot's announcement: a replay
  server.seen = Clock::now();
  server.free = announce.capacity - announce.active_matches;
  server.boot_ms = boot_ms;
  replay_games_of_earlier_boots(announce.server_id, boot_ms);
}

void TournamentRunner::replay_games_of_earlier_boots(const std::string& server,
                                                     std::int64_t boot_ms) {
  for (auto& g : games_) {
    if (g.status != GameStatus::Dispatched || g.server_id != server || g.match_id.empty()) continue;
    const auto match_boot = protocol::match_boot_ms(g.match_id);
    if (match_boot && *match_boot < boot_ms)
      return retry(g, "server " + server + " restarted: match " + g.match_id +
                          " of its earlier run was aborted");  // in_flight_ changed: next time
  }
}

bool TournamentRunner::usable(const Server& s, Clock::time_point now) const {
  return now - s.seen <= std::chrono::duration<double>(settings_.server_silence_s) &&
         now >= s.shunned_until;
}

// Asks the scheduler for more games when another could start; false once it has finished and
// every game is done.
bool TournamentRunner::schedule_more() {
  int open = 0;
  for (const auto& g : games_) open += g.status != GameStatus::Done;
  if (open >= settings_.parallel) return true;
  std::vector<Pairing> pairs;
  const size_t entrants_before = spec_.entrants.size();
  switch (scheduler_->schedule(spec_, games_, pairs)) {
    case Scheduler::Verdict::Finished:
      return open > 0;
    case Scheduler::Verdict::Wait:
      return true;
    case Scheduler::Verdict::Added:
      break;
  }
  if (spec_.entrants.size() != entrants_before) store_.update_entrants(spec_);
  std::vector<Game> added;
  for (const auto& p : pairs) {
    Game g;
    g.index = static_cast<int>(games_.size() + added.size());
    g.round = p.round, g.home = p.home, g.away = p.away, g.seats = p.seats;
    if (p.away < 0) g.status = GameStatus::Done, g.home_score = 1, g.reason = "bye";
    added.push_back(g);
  }
  store_.add_games(spec_.name, added);
  games_.insert(games_.end(), added.begin(), added.end());
  return true;
}

void TournamentRunner::dispatch() {
  const auto now = Clock::now();
  if (now - started_ < kFirstListen && !heard_every_named_server()) return;
  for (auto& g : games_) {
    if (static_cast<int>(in_flight_.size()) >= settings_.parallel) return;
    if (g.status != GameStatus::Pending) continue;
    // The live server with the most room, by id on a tie.
    std::string best;
    int room = 0;
    for (auto& [id, s] : servers_) {
      if (!usable(s, now)) continue;
      if (s.free > room) best = id, room = s.free;
    }
    if (best.empty()) return;
    --servers_[best].free;
    g.status = GameStatus::Dispatched;
    g.server_id = best;
    g.request_id = spec_.name + "-g" + std::to_string(g.index) + "-a" + std::to_string(g.attempt);
    g.match_id.clear();
    save(g);  // before asking, so a restart asks again with the same id
    in_flight_[g.index].dispatched = now;
  }
}

bool TournamentRunner::heard_every_named_server() const {
  if (settings_.servers.empty()) return false;
  for (const auto& id : settings_.servers)
    if (!servers_.contains(id)) return false;
  return true;
}

void TournamentRunner::keep_in_touch() {
  const auto now = Clock::now();
  for (auto& [index, f] : in_flight_) {
    Game& g = games_[index];
    // A server is gone when it fell silent, or never spoke since this run started.
    const auto silence = std::chrono::duration<double>(settings_.server_silence_s);
    auto server = servers_.find(g.server_id);
    const bool gone =
        server != servers_.end() ? now - server->second.seen > silence : now - started_ > silence;
    if (gone) {
      retry(g, "server " + g.server_id + " stopped announcing");
      return;  // in_flight_ changed
    }
    // A live server that does not answer (it hears some messages only, or is stuck): another
    // one gets the game, and this one none for a while.
    const auto wait = std::chrono::duration<double>(settings_.server_wait_s);
    if (f.slot_teams.empty() && f.dispatched != Clock::time_point{} && now - f.dispatched > wait) {
      if (server != servers_.end())
        server->second.shunned_until = now + std::chrono::duration_cast<Clock::duration>(2 * wait);
      retry(g, "server " + g.server_id + " announces itself but did not answer the request for " +
                   "game " + std::to_string(g.index) + " in " +
                   std::to_string(static_cast<int>(settings_.server_wait_s)) +
                   " s (--server-wait-s); no game goes to it for twice as long");
      return;  // in_flight_ changed
    }
    // Until the server has described the match (also after a restart of the league), ask again:
    // a request id it has seen gets the same match.
    if (f.slot_teams.empty() && now - f.last_request >= kRequestResend) {
      olympics::match_request_t r;
      r.protocol_version = protocol::kProtocolVersion;
      r.request_id = g.request_id;
      r.server_id = g.server_id;
      r.sport = spec_.sport;
      r.mode = spec_.mode;
      r.seed = static_cast<std::int64_t>(spec_.seed * 1000 + static_cast<std::uint64_t>(g.index));
      r.time_limit_s = static_cast<float>(spec_.time_limit_s);
      r.realtime = false;
      r.options = spec_.sport_options;
      transport_.publish(protocol::kRequest, r);
      f.last_request = now;
    }
    if (!g.match_id.empty() && !f.slot_teams.empty() && now - f.last_probe >= kProbeInterval) {
      assign_live(g);
      // Any message about a finished match makes its server say the result again.
      olympics::heartbeat_t h;
      h.protocol_version = protocol::kProtocolVersion;
      h.match_id = g.match_id;
      h.client_id = league_probe_id();
      transport_.publish(protocol::kHeartbeat, h);
      f.last_probe = now;
    }
  }
}

void TournamentRunner::on_created(const olympics::match_created_t& created) {
  Game* g = game_by_request(created.request_id);
  if (!g) return;
  InFlight& f = in_flight_[g->index];
  if (!f.slot_teams.empty()) return;  // a repeated answer
  std::vector<int> teams(created.slot_team.begin(), created.slot_team.end());
  const int team_count = static_cast<int>(g->entrants().size());
  bool every_team_plays = true;
  for (int t = 0; t < team_count; ++t)
    every_team_plays = every_team_plays && std::count(teams.begin(), teams.end(), t) > 0;
  if (!every_team_plays ||
      std::any_of(teams.begin(), teams.end(), [&](int t) { return t < 0 || t >= team_count; })) {
    if (g->ranked())
      return stop("the league seats " + std::to_string(team_count) + " entrants, a team each, in " +
                  "every match of " + spec_.sport + " " + spec_.mode +
                  ", but the server's match has other teams (a ranked mode is competition_N: N "
                  "athletes, each its own team)");
    return stop(
        "the league plays modes of two teams, or ranked competitions of N (competition_N); " +
        spec_.sport + " " + spec_.mode + " has other teams (choose 1v1, 2v2, ...)");
  }
  f.slot_teams = teams;
  if (g->match_id.empty()) {
    g->match_id = created.match_id;
    save(*g);  // before the workers start, so a restart knows which match to look for
  }
  if (!f.workers_started) start_workers(*g);
}

// A server refused a game's request: a bad tournament spec (unknown sport or mode, a bad
// setting) ends the run; a full server is asked again later. A server that restarted after a
// crash answers the league's probe of a game's match (league_probe_id()) with UNKNOWN_MATCH: it
// has recorded the match as aborted, and the game is played again.
void TournamentRunner::on_error(const olympics::error_t& error) {
  for (auto& g : games_) {
    if (g.status != GameStatus::Dispatched || g.server_id != error.server_id) continue;
    if (error.code == "UNKNOWN_MATCH" && !g.match_id.empty() && error.match_id == g.match_id &&
        error.client_id == league_probe_id())
      return retry(g, "server " + g.server_id + " no longer knows match " + g.match_id +
                          " (it restarted and recorded the match as aborted)");
    if (error.message.rfind("request " + g.request_id + ":", 0) != 0) continue;
    if (error.code == "FULL") return retry(g, error.message);
    return stop("server " + error.server_id + " refused game " + std::to_string(g.index) + ": " +
                error.code + ": " + error.message);
  }
}

std::string TournamentRunner::league_probe_id() const { return "league-" + spec_.name; }

void TournamentRunner::start_workers(Game& g) {
  InFlight& f = in_flight_[g.index];
  f.workers_started = true;
  f.last_request = Clock::now();
  assign_live(g);
  const std::vector<int> seated = g.entrants();
  const char* timeout_s =
      std::any_of(seated.begin(), seated.end(), [&](int e) { return spec_.entrants[e].is_live(); })
          ? kAgentTimeoutWithLiveLearnerS
          : kAgentTimeoutS;
  for (int team = 0; team < static_cast<int>(seated.size()); ++team) {
    const Entrant& e = spec_.entrants[seated[team]];
    if (e.is_live()) continue;  // a live learner joins by itself: assign_live()
    const auto copy = settings_.policy_files.find(e.policy);
    const std::string policy =
        copy == settings_.policy_files.end() ? e.policy : "mlp:" + copy->second;
    std::vector<std::string> argv = {settings_.agent_program,
                                     "--match",
                                     g.match_id,
                                     "--slots",
                                     slots_argument(team_slots(f.slot_teams, team)),
                                     "--policy",
                                     policy,
                                     "--policy-seed",
                                     std::to_string(e.seed),
                                     "--name",
                                     e.name,
                                     "--policy-id",
                                     e.policy,
                                     "--timeout",
                                     timeout_s};
    if (!settings_.lcm_url.empty()) argv.insert(argv.end(), {"--lcm-url", settings_.lcm_url});
    if (!settings_.secret_file.empty())
      argv.insert(argv.end(), {"--secret", settings_.secret_file});
    f.workers.push_back(std::make_unique<Process>(
        argv, settings_.log_dir + "/" + g.match_id + "-team" + std::to_string(team) + ".log"));
  }
}

// Tells the live learners among the game's entrants which match and slots to play.
void TournamentRunner::assign_live(const Game& g) {
  const std::vector<int> seated = g.entrants();
  for (int team = 0; team < static_cast<int>(seated.size()); ++team) {
    const Entrant& e = spec_.entrants[seated[team]];
    if (!e.is_live()) continue;
    olympics::league_assignment_t a;
    a.protocol_version = protocol::kProtocolVersion;
    a.league = spec_.name;
    a.learner = e.policy.substr(5);
    a.game = g.index;
    a.match_id = g.match_id;
    a.slots = team_slots(in_flight_.at(g.index).slot_teams, team);
    a.num_slots = static_cast<int>(a.slots.size());
    a.opponent.clear();  // the others, in seat order
    for (int other = 0; other < static_cast<int>(seated.size()); ++other)
      if (other != team)
        a.opponent += (a.opponent.empty() ? "" : ",") + spec_.entrants[seated[other]].name;
    transport_.publish(protocol::kLeague, a);
  }
}

void TournamentRunner::on_result(const olympics::match_result_t& result) {
  for (auto& g : games_) {
    if (g.status != GameStatus::Dispatched || g.match_id != result.match_id) continue;
    // Only the server the game was given to decides it (with a secret, only a real one can).
    if (result.server_id != g.server_id) return;
    if (result.reason.rfind("cancelled", 0) == 0 || result.reason.rfind("aborted", 0) == 0)
      return retry(g, result.reason);
    g.status = GameStatus::Done;
    g.home_score = result.winner_team == 0 ? 1.0 : result.winner_team == 1 ? 0.0 : 0.5;
    if (g.ranked()) {
      g.places = ranked_places(result.info, static_cast<int>(g.seats.size()), result.winner_team);
      g.home_score = pair_score(g.places[0], g.places[1]);
    }
    g.reason = result.reason;
    g.ticks = result.ticks;
    save(g);
    if (settings_.on_game_done) settings_.on_game_done(g);
    in_flight_.erase(g.index);
    show_progress();
    return;
  }
}

void TournamentRunner::retry(Game& g, const std::string& why) {
  std::string who;
  for (int e : g.entrants()) who += (who.empty() ? "" : " vs ") + spec_.entrants[e].name;
  std::fprintf(stderr, "\ngame %d (%s): %s; trying again\n", g.index, who.c_str(), why.c_str());
  g.status = GameStatus::Pending;
  ++g.attempt;
  g.match_id.clear();
  save(g);
  in_flight_.erase(g.index);
}

void TournamentRunner::show_progress() {
  if (!settings_.progress) return;
  int done = 0;
  for (const auto& g : games_) done += g.status == GameStatus::Done;
  const int total = static_cast<int>(games_.size()), width = 30;
  const int filled = total ? width * done / total : 0;
  std::fprintf(stderr, "\r%s [%s%s] %d/%d games", spec_.name.c_str(),
               std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(), done,
               total);
  if (done == total) std::fprintf(stderr, "\n");
}

// Servers announce the sports they host: when some have been heard for a while and none hosts the
// tournament's sport, waiting longer will not help.
void TournamentRunner::refuse_if_no_server_offers_the_sport() {
  const auto waited = std::chrono::duration<double>(Clock::now() - started_).count();
  if (!servers_.empty() || other_servers_.empty() || waited < settings_.server_silence_s) return;
  std::string seen;
  for (const auto& [id, sports] : other_servers_)
    seen += (seen.empty() ? "" : "; ") + id + ": " + sports;
  stop("no server hosts the sport \"" + spec_.sport + "\" (servers heard: " + seen + ")");
}

// No usable server has been live for server_wait_s: none runs on this URL, the named ones do not
// exist, or their announcements fail the signature check. Waiting on in silence helps nobody.
void TournamentRunner::stop_if_no_server_is_heard() {
  const auto now = Clock::now();
  for (const auto& [id, s] : servers_)
    if (usable(s, now)) last_server_heard_ = now;
  if (now - last_server_heard_ < std::chrono::duration<double>(settings_.server_wait_s)) return;
  std::string named;
  for (const auto& id : settings_.servers) named += (named.empty() ? "" : ", ") + id;
  std::string why = "no server" + (named.empty() ? "" : " of --servers " + named) +
                    " announced itself on " + transport_.url() + " for " +
                    std::to_string(static_cast<int>(settings_.server_wait_s)) +
                    " s; is olympics-server running there (olympics-server serve --id ID)?";
  std::string mute;
  for (const auto& [id, s] : servers_)
    if (now < s.shunned_until) mute += (mute.empty() ? "" : ", ") + id;
  if (!mute.empty())
    why = "no server answered the league's requests for " +
          std::to_string(static_cast<int>(settings_.server_wait_s)) +
          " s (--server-wait-s): " + mute +
          " announce(s) themselves but left requests unanswered (a server that hears only some "
          "messages, or is stuck: see its log)";
  if (transport_.unauthenticated() > 0)
    why += " " + std::to_string(transport_.unauthenticated()) +
           " message(s) heard failed the signature check: the servers may use another secret "
           "than --secret, or none";
  stop(why);
}

// Called from LCM's callbacks, which must not throw: run() throws once the callback returned.
void TournamentRunner::stop(const std::string& why) {
  if (fatal_.empty()) fatal_ = why;
}

void TournamentRunner::run() {
  started_ = last_server_heard_ = Clock::now();
  for (;;) {
    if (!schedule_more()) break;
    dispatch();
    keep_in_touch();
    transport_.handle(10);
    refuse_if_no_server_offers_the_sport();
    stop_if_no_server_is_heard();
    if (!fatal_.empty()) throw std::invalid_argument(fatal_);
  }
  show_progress();
}

}  // namespace olympics::selfplay
