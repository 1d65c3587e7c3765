// The tournament table: standings with Weng-Lin and Elo ratings, recomputed from the stored games
// in game order (so a resumed league prints exactly what an uninterrupted one would), and a plot
// of the ratings over the games.
#pragma once

#include <string>
#include <vector>

#include "league_store.h"
#include "payoff.h"
#include "ratings.h"
#include "tournament.h"

namespace olympics::selfplay {

struct TableRow {
  Standing standing;
  std::string name;
  SkillRating skill;
  double elo = 1500;
};

struct Leaderboard {
  std::vector<TableRow> rows;                   // table order
  PayoffMatrix payoff;                          // by entrant index, decay 0.99
  std::vector<std::vector<double>> mu_history;  // per entrant, after each finished game
};

Leaderboard compute_leaderboard(const TournamentSpec& spec, const std::vector<Game>& games);
std::string format_table(const Leaderboard& board);
// The payoff matrix: each row entrant's decayed win rate against each column ("-": never met).
std::string format_payoff(const TournamentSpec& spec, const Leaderboard& board);
// An SVG line chart of every entrant's Weng-Lin mu after each game.
std::string ratings_svg(const TournamentSpec& spec, const Leaderboard& board);

}  // namespace olympics::selfplay
