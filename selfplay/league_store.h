// The league's state in SQL (a SQLite file, or PostgreSQL by URL): tournaments and every game with
// its progress, written before each step is taken, so a league killed at any moment (kill -9)
// resumes where it was.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace olympics::sql {
class SqlDatabase;
}

namespace olympics::selfplay {

struct Entrant {
  std::string name;    // unique in the tournament
  std::string policy;  // what olympics-agent plays: zero, random, scripted, mlp:FILE; or live:NAME
  std::uint64_t seed = 0;
  // A trainer's client that joins the matches the league assigns it (live:NAME), not a process
  // the league starts.
  bool is_live() const { return policy.rfind("live:", 0) == 0; }
};

struct TournamentSpec {
  std::string name;
  std::string format;   // round-robin, double-round-robin, swiss, knockout, selfplay
  std::string options;  // JSON: the scheduler's settings (self-play), "{}" for tournaments
  std::string sport = "sandbox";
  std::string mode = "1v1";
  std::uint64_t seed = 1;
  double time_limit_s = 0;
  std::string sport_options = "{}";  // JSON: the sport's settings, sent with every match request
  std::vector<Entrant> entrants;
};

enum class GameStatus { Pending, Dispatched, Done };

struct Game {
  int index = 0;
  int round = 0;
  int home = 0, away = 0;  // entrant indices; away < 0 is a bye
  GameStatus status = GameStatus::Pending;
  int attempt = 0;
  std::string request_id, server_id, match_id;
  double home_score = 0;  // 1 win, 0.5 draw, 0 loss
  std::string reason;
  int ticks = 0;
  // A ranked fixture of N entrants (an athletics competition_N): seats[t] plays team t (home and
  // away are seats[0] and seats[1]); its result is places[t] per team, 1 = first, equal places
  // tie (the match's info["places"]). Both empty for a two-team game.
  std::vector<int> seats;
  std::vector<int> places;
  bool ranked() const { return !seats.empty(); }
  // Who plays, team by team: the seats, or home and away.
  std::vector<int> entrants() const { return ranked() ? seats : std::vector<int>{home, away}; }
};

// A list of integers as stored in a text column (a JSON array; "" for none), and back.
std::string int_list_text(const std::vector<int>& values);
std::vector<int> int_list_from_text(const std::string& text);

class LeagueStore {
 public:
  explicit LeagueStore(const std::string& location);  // throws with what to check
  ~LeagueStore();
  LeagueStore(const LeagueStore&) = delete;
  LeagueStore& operator=(const LeagueStore&) = delete;

  std::optional<TournamentSpec> find_tournament(const std::string& name);
  std::vector<std::string> tournament_names();
  void create_tournament(const TournamentSpec& spec);
  void update_entrants(const TournamentSpec& spec);  // entrants that joined since (snapshots)
  std::vector<Game> games(const std::string& tournament);
  void add_games(const std::string& tournament, const std::vector<Game>& games);
  void update_game(const std::string& tournament, const Game& game);

 private:
  std::unique_ptr<sql::SqlDatabase> db_;
};

}  // namespace olympics::selfplay
