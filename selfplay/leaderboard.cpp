#include "leaderboard.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace olympics::selfplay {

namespace {

// A ranked game of N entrants (places per seat): one Weng-Lin update of N teams of one ranked by
// their places, pairwise Elo (elo_ranked), and each pair of seats as a game in the standings and
// the payoff matrix (the better place wins, equal places draw). For N = 2 this is exactly what a
// two-team game with the same result gives.
void rate_ranked_game(const Game& g, std::vector<SkillRating>& skill, std::vector<double>& elo,
                      std::vector<GameResult>& results, PayoffMatrix& payoff) {
  const size_t n = g.seats.size();
  if (g.places.size() != n) return;  // a result stored without places: nothing to rate
  std::vector<std::vector<SkillRating>> teams;
  std::vector<double> elo_before;
  for (int e : g.seats) teams.push_back({skill[e]}), elo_before.push_back(elo[e]);
  const auto rated = rate_match(teams, g.places);
  const auto elo_after = elo_ranked(elo_before, g.places);
  for (size_t i = 0; i < n; ++i) skill[g.seats[i]] = rated[i][0], elo[g.seats[i]] = elo_after[i];
  for (size_t a = 0; a < n; ++a)
    for (size_t b = a + 1; b < n; ++b) {
      const double score = pair_score(g.places[a], g.places[b]);
      results.push_back({g.seats[a], g.seats[b], score});
      payoff.record(g.seats[a], g.seats[b], score);
    }
}

}  // namespace

Leaderboard compute_leaderboard(const TournamentSpec& spec, const std::vector<Game>& games) {
  const int n = static_cast<int>(spec.entrants.size());
  std::vector<SkillRating> skill(n);
  std::vector<double> elo(n, 1500);
  std::vector<GameResult> results;
  Leaderboard board;
  board.payoff = PayoffMatrix(n);
  board.mu_history.assign(n, {});
  for (int i = 0; i < n; ++i) board.mu_history[i].push_back(skill[i].mu);
  for (const auto& g : games) {  // in game order, whatever order they finished in
    // A policy against itself says nothing about its strength: no points, no rating change.
    if (g.status != GameStatus::Done || g.home == g.away) continue;
    if (g.ranked()) {
      rate_ranked_game(g, skill, elo, results, board.payoff);
      for (int i = 0; i < n; ++i) board.mu_history[i].push_back(skill[i].mu);
      continue;
    }
    results.push_back({g.home, g.away, g.home_score});
    if (g.away < 0) continue;
    const int home_rank = g.home_score > 0.5 ? 0 : 1, away_rank = g.home_score < 0.5 ? 0 : 1;
    auto rated = rate_match({{skill[g.home]}, {skill[g.away]}}, {home_rank, away_rank});
    skill[g.home] = rated[0][0], skill[g.away] = rated[1][0];
    board.payoff.record(g.home, g.away, g.home_score);
    auto e = elo_update(elo[g.home], elo[g.away], g.home_score);
    elo[g.home] = e.a, elo[g.away] = e.b;
    for (int i = 0; i < n; ++i) board.mu_history[i].push_back(skill[i].mu);
  }
  for (const auto& s : standings(n, results))
    board.rows.push_back({s, spec.entrants[s.entrant].name, skill[s.entrant], elo[s.entrant]});
  return board;
}

std::string format_table(const Leaderboard& board) {
  std::ostringstream out;
  char line[200];
  std::snprintf(line, sizeof line, "%-4s %-16s %6s %4s %4s %4s %4s %8s %8s %8s\n", "#", "entrant",
                "points", "W", "D", "L", "bye", "mu", "ordinal", "elo");
  out << line;
  int place = 1;
  for (const auto& r : board.rows) {
    std::snprintf(line, sizeof line, "%-4d %-16s %6.1f %4d %4d %4d %4d %8.2f %8.2f %8.1f\n",
                  place++, r.name.c_str(), r.standing.points, r.standing.wins, r.standing.draws,
                  r.standing.losses, r.standing.byes, r.skill.mu, r.skill.ordinal(), r.elo);
    out << line;
  }
  return out.str();
}

std::string format_payoff(const TournamentSpec& spec, const Leaderboard& board) {
  std::ostringstream out;
  char cell[64];
  out << "payoff: row's decayed win rate against column (draw = half; - never met)\n";
  std::snprintf(cell, sizeof cell, "%-16s", "");
  out << cell;
  for (const auto& e : spec.entrants) {
    std::snprintf(cell, sizeof cell, " %10.10s", e.name.c_str());
    out << cell;
  }
  out << "\n";
  for (int a = 0; a < board.payoff.size(); ++a) {
    std::snprintf(cell, sizeof cell, "%-16s", spec.entrants[a].name.c_str());
    out << cell;
    for (int b = 0; b < board.payoff.size(); ++b) {
      if (a == b || board.payoff.games(a, b) == 0)
        std::snprintf(cell, sizeof cell, " %10s", "-");
      else
        std::snprintf(cell, sizeof cell, " %10.2f", board.payoff.win_rate(a, b));
      out << cell;
    }
    out << "\n";
  }
  return out.str();
}

std::string ratings_svg(const TournamentSpec& spec, const Leaderboard& board) {
  const double width = 720, height = 360, margin = 40, legend = 110;
  double lo = 1e9, hi = -1e9;
  size_t points = 1;
  for (const auto& h : board.mu_history) {
    for (double v : h) lo = std::min(lo, v), hi = std::max(hi, v);
    points = std::max(points, h.size());
  }
  if (hi - lo < 1) lo -= 1, hi += 1;
  auto x = [&](size_t i) {
    return margin + (width - margin - legend) * i / std::max<size_t>(1, points - 1);
  };
  auto y = [&](double v) { return height - margin - (height - 2 * margin) * (v - lo) / (hi - lo); };
  const char* colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728",
                           "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" "
         "fill=\"white\"/>\n"
      << "<text x=\"" << margin << "\" y=\"20\">" << spec.name
      << ": Weng-Lin mu after each game</text>\n"
      << "<line x1=\"" << margin << "\" y1=\"" << height - margin << "\" x2=\"" << width - legend
      << "\" y2=\"" << height - margin << "\" stroke=\"black\"/>\n<line x1=\"" << margin
      << "\" y1=\"" << margin << "\" x2=\"" << margin << "\" y2=\"" << height - margin
      << "\" stroke=\"black\"/>\n";
  char label[64];
  std::snprintf(label, sizeof label, "%.1f", hi);
  svg << "<text x=\"4\" y=\"" << margin + 4 << "\">" << label << "</text>\n";
  std::snprintf(label, sizeof label, "%.1f", lo);
  svg << "<text x=\"4\" y=\"" << height - margin << "\">" << label << "</text>\n";
  for (size_t e = 0; e < board.mu_history.size(); ++e) {
    const char* colour = colours[e % 8];
    svg << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\" points=\"";
    for (size_t i = 0; i < board.mu_history[e].size(); ++i)
      svg << x(i) << "," << y(board.mu_history[e][i]) << " ";
    svg << "\"/>\n<text x=\"" << width - legend + 6 << "\" y=\""
        << y(board.mu_history[e].back()) + 4 << "\" fill=\"" << colour << "\">"
        << spec.entrants[e].name << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace olympics::selfplay
