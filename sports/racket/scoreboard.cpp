#include "racket/scoreboard.h"

#include <cstdio>

namespace olympics::sports::racket {
namespace {

// -1, 0 or 1: which of a pair is larger.
int larger(const std::array<int, 2>& a) { return a[0] == a[1] ? -1 : (a[0] > a[1] ? 0 : 1); }

std::string pair_text(const std::array<int, 2>& a) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%d-%d", a[0], a[1]);
  return buf;
}

// Finished sets or games, "6-4 3-6", then (while the match goes on) a space before the rest.
std::string history_text(const std::vector<std::array<int, 2>>& finished, bool over) {
  std::string out;
  for (const auto& f : finished) {
    if (!out.empty()) out += ' ';
    out += pair_text(f);
  }
  return over || out.empty() ? out : out + " ";
}

// Won when reaching `target` with a lead of 2.
bool won_by_two(const std::array<int, 2>& a, int team, int target) {
  return a[team] >= target && a[team] - a[1 - team] >= 2;
}

}  // namespace

TennisScore::TennisScore(const TennisFormat& format, int first_server)
    : format_(format), game_server_(first_server) {}

bool TennisScore::in_tiebreak() const {
  return format_.tiebreak_only ||
         (games_[0] == format_.games_per_set && games_[1] == format_.games_per_set);
}

int TennisScore::server() const {
  if (!in_tiebreak()) return game_server_;
  // Tie-break: the first point by the game's server, then two each, alternately.
  const int n = points_[0] + points_[1];
  return ((n + 1) / 2) % 2 == 0 ? game_server_ : 1 - game_server_;
}

void TennisScore::point_won(int team) {
  if (over()) return;
  ++points_played_;
  ++points_[team];
  if (in_tiebreak()) {
    if (won_by_two(points_, team, format_.tiebreak_points)) game_won(team);
  } else if (won_by_two(points_, team, 4)) {  // 15, 30, 40, game (deuce and advantage by two)
    game_won(team);
  }
}

void TennisScore::game_won(int team) {
  const bool tiebreak = in_tiebreak();
  points_ = {0, 0};
  ++games_[team];
  game_server_ = 1 - game_server_;
  const int g = format_.games_per_set;
  if (tiebreak || won_by_two(games_, team, g)) {
    finished_sets_.push_back(games_);
    games_ = {0, 0};
    if (++sets_[team] == format_.sets_to_win) winner_ = team;
  }
}

std::array<float, 2> TennisScore::scores() const {
  return {static_cast<float>(sets_[0]), static_cast<float>(sets_[1])};
}

int TennisScore::leader() const {
  if (int s = larger(sets_); s >= 0) return s;
  if (int g = larger(games_); g >= 0) return g;
  return larger(points_);
}

std::string TennisScore::text() const {
  if (over()) return history_text(finished_sets_, true);
  std::string out = history_text(finished_sets_, false) + pair_text(games_) + " ";
  if (in_tiebreak()) return out + "tie-break " + pair_text(points_);
  static const char* kCalls[] = {"0", "15", "30", "40"};
  if (points_[0] >= 3 && points_[1] >= 3) {
    if (points_[0] == points_[1]) return out + "deuce";
    return out + "advantage " + std::to_string(points_[0] > points_[1] ? 0 : 1);
  }
  return out + kCalls[points_[0]] + "-" + kCalls[points_[1]];
}

nlohmann::json TennisScore::to_json() const {
  nlohmann::json sets = nlohmann::json::array();
  for (const auto& s : finished_sets_) sets.push_back(s);
  return {{"sets_won", sets_}, {"set_scores", sets},        {"games", games_},
          {"points", points_}, {"tiebreak", in_tiebreak()}, {"server", server()},
          {"text", text()},    {"winner", winner_},         {"points_played", points_played_}};
}

TableTennisScore::TableTennisScore(const TableTennisFormat& format, int first_server)
    : format_(format), game_first_server_(first_server) {}

int TableTennisScore::server() const {
  // Two serves each; from 10-10 (deuce) one each.
  const int n = points_[0] + points_[1];
  const int deuce_at = 2 * (format_.points_per_game - 1);
  const int turns = n < deuce_at ? n / 2 : deuce_at / 2 + (n - deuce_at);
  return turns % 2 == 0 ? game_first_server_ : 1 - game_first_server_;
}

void TableTennisScore::point_won(int team) {
  if (over()) return;
  ++points_played_;
  ++points_[team];
  if (!won_by_two(points_, team, format_.points_per_game)) return;
  finished_games_.push_back(points_);
  points_ = {0, 0};
  game_first_server_ = 1 - game_first_server_;  // the other side serves first in the next game
  if (++games_[team] == format_.games_to_win) winner_ = team;
}

std::array<float, 2> TableTennisScore::scores() const {
  return {static_cast<float>(games_[0]), static_cast<float>(games_[1])};
}

int TableTennisScore::leader() const {
  if (int g = larger(games_); g >= 0) return g;
  return larger(points_);
}

std::string TableTennisScore::text() const {
  return history_text(finished_games_, over()) + (over() ? "" : pair_text(points_));
}

nlohmann::json TableTennisScore::to_json() const {
  nlohmann::json games = nlohmann::json::array();
  for (const auto& g : finished_games_) games.push_back(g);
  return {{"games_won", games_},
          {"game_scores", games},
          {"points", points_},
          {"server", server()},
          {"text", text()},
          {"winner", winner_},
          {"points_played", points_played_}};
}

}  // namespace olympics::sports::racket
