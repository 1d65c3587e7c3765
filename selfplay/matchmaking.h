// Self-play matchmaking: the learner against opponents chosen by a strategy, one game at a time
// (so swaps happen only between matches). The learner is its latest snapshot, or (`learner`)
// a live learner: the trainer's own client plays its games (entrant live:NAME) while the
// snapshots it publishes and the bots are its opponents.
//
// Strategies (the anchors of the league issue):
//   latest          latest vs latest (shared-policy self-play; a live learner meets its newest
//                   snapshot)
//   alternating:E   a frozen copy: the opponent is the snapshot that was latest at the start of
//                   each block of E games (the original's two policies taking turns to learn)
//   mlagents:R      ML-Agents: with probability R the latest, else uniform from the window
//   pfsp[:W]        PFSP over the window and the bots, weighting W (hard, variance, linear, even,
//                   capped) of the latest's decayed win rate against each
// and --bot-share S: with probability S a bot instead, before the strategy.
//
// Every decision is a pure function of the seed, the game's index and the results of games at
// least `lag` (= games in flight) before it, so a resumed league decides exactly as an
// uninterrupted one would.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "payoff.h"
#include "scheduler.h"

namespace olympics::selfplay {

struct SelfplayOptions {
  std::string snapshots_dir;  // the learner writes <anything>v<N>.safetensors here
  int window = 5;             // past snapshots kept as opponents
  std::string strategy = "pfsp:hard";
  double bot_share = 0;
  int matches = 20;
  int lag = 2;          // the runner's games in flight
  std::string learner;  // a live learner's name: it plays the learning side ("" : the latest)
  nlohmann::json to_json() const;
  static SelfplayOptions from_json(const std::string& text);
};

struct Roster {
  int latest = -1;          // entrant index of the learner: the newest snapshot, or the live one
  std::vector<int> window;  // snapshots it may meet, newest first, at most `window`
  std::vector<int> bots;
  int mirror = -1;  // who "itself" is as an opponent: latest, or a live one's newest
                    // snapshot (-1: none yet)
};

// The opponent of roster.latest in game `game` (-1: nobody to play yet). `games` are the games
// before it (for alternating).
int choose_opponent(const SelfplayOptions& options, const Roster& roster,
                    const PayoffMatrix& payoff, int game, std::uint64_t seed,
                    const std::vector<Game>& games);

class SelfplayScheduler : public Scheduler {
 public:
  explicit SelfplayScheduler(SelfplayOptions options) : options_(std::move(options)) {}
  Verdict schedule(TournamentSpec& spec, const std::vector<Game>& games,
                   std::vector<Pairing>& out) override;

 private:
  void scan_snapshots(TournamentSpec& spec);
  SelfplayOptions options_;
};

// The snapshot version in a file name ("policy-v12.safetensors" -> 12), -1 if none.
int snapshot_version(const std::string& file_name);

}  // namespace olympics::selfplay
