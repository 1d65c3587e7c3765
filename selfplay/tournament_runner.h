// Plays a tournament or a self-play run to its end over the olympics-servers on the LCM network:
// takes games from its Scheduler (tournament rounds, or matchmaking), dispatches each to a
// server with room (from the servers' announcements), starts a policy worker (olympics-agent)
// per slot, records every result, and retries a game whose server died or cancelled it. Every
// step is written to the LeagueStore before it is taken, so a killed league resumes.
#pragma once

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "league_store.h"
#include "olympics/error_t.hpp"
#include "olympics/match_created_t.hpp"
#include "olympics/match_result_t.hpp"
#include "olympics/server_announce_t.hpp"
#include "process.h"
#include "scheduler.h"
#include "transport.h"

namespace olympics::selfplay {

struct RunnerSettings {
  std::string lcm_url;
  std::vector<std::string> servers;  // allowed server ids; empty = any that announces
  int parallel = 2;                  // games in flight at once
  std::string agent_program;         // path of olympics-agent
  std::string log_dir = "/tmp";      // policy workers' output
  double server_silence_s = 5;       // a server not announcing this long is gone
  double server_wait_s = 60;         // no usable server heard this long: stop, saying so; a
                                     // request unanswered this long: another server is tried
  bool progress = true;              // a progress bar on stderr
  std::string secret_file;           // "" = $OLYMPICS_SECRET_FILE, or none; its workers get it too
  // Told each game's result once it is stored (a fleet's cell hands it on to the queue).
  std::function<void(const Game&)> on_game_done;
  // Where this host reads an entrant's snapshot when not from its stored path (a fleet's cell
  // plays its own copy of mlp:FILE): stored policy -> file.
  std::map<std::string, std::string> policy_files;
};

// The slots of `team` from a match's slot-to-team mapping (match_created_t.slot_team), in slot
// order. Each entrant plays all the slots of its team.
std::vector<int> team_slots(const std::vector<int>& slot_teams, int team);

// A ranked fixture's result from its match: info["places"] (the referee's place per team, 1 =
// first, equal places tie), when it holds a place >= 1 for each of `teams`; otherwise the
// winner first and everyone else tied second (winner_team -1: all tied).
std::vector<int> ranked_places(const std::string& info, int teams, int winner_team);

class TournamentRunner {
 public:
  TournamentRunner(LeagueStore& store, TournamentSpec spec, RunnerSettings settings,
                   std::unique_ptr<Scheduler> scheduler);
  ~TournamentRunner();
  // Returns when every game has a result; throws std::invalid_argument when the servers refuse
  // the tournament's sport, mode or settings.
  void run();

 private:
  using Clock = std::chrono::steady_clock;
  struct Server {
    Clock::time_point seen;
    int free = 0;
    std::int64_t boot_ms = 0;  // the newest boot it announced
    // It announced itself but left a request unanswered for server_wait_s: no game goes to it
    // for twice that (it may be stuck, or hear only some of what is sent), so that with no other
    // server the run stops (stop_if_no_server_is_heard) rather than ask it again and again.
    Clock::time_point shunned_until{};
  };
  struct InFlight {
    Clock::time_point dispatched, last_request, last_probe;
    std::vector<int> slot_teams;  // from the server's description of the match
    bool workers_started = false;
    std::vector<std::unique_ptr<Process>> workers;
  };

  bool schedule_more();
  void dispatch();
  bool heard_every_named_server() const;  // each of --servers has announced
  void on_created(const olympics::match_created_t& created);
  void on_result(const olympics::match_result_t& result);
  void on_announce(const olympics::server_announce_t& announce);
  void on_error(const olympics::error_t& error);
  std::string league_probe_id() const;  // the client id of its heartbeats about its games
  void stop(const std::string& why);
  void refuse_if_no_server_offers_the_sport();
  void stop_if_no_server_is_heard();
  void start_workers(Game& game);
  void assign_live(const Game& game);
  void retry(Game& game, const std::string& why);
  void keep_in_touch();
  // Games whose match belongs to an earlier boot of `server` than it announces: that boot is
  // gone and the match was recorded as aborted when the server came back.
  void replay_games_of_earlier_boots(const std::string& server, std::int64_t boot_ms);
  bool usable(const Server& s, Clock::time_point now) const;
  void save(const Game& game);
  void show_progress();
  Game* game_by_request(const std::string& request_id);

  std::unique_ptr<Scheduler> scheduler_;
  LeagueStore& store_;
  TournamentSpec spec_;
  RunnerSettings settings_;
  protocol::Transport transport_;
  std::vector<Game> games_;
  std::map<int, InFlight> in_flight_;                 // by game index
  std::map<std::string, Server> servers_;             // those that host the sport
  std::map<std::string, std::string> other_servers_;  // id -> the sports it hosts
  Clock::time_point started_;
  Clock::time_point last_server_heard_;  // a usable server was live (or the run started)
  std::string fatal_;                    // why the run cannot go on (a bad spec the servers refuse)
};

}  // namespace olympics::selfplay
