// Scoring beyond the original (which has none): tennis points, games and tie-break sets, and
// table-tennis games to 11, each with its match format. Pure bookkeeping: the referee decides who
// won a point, the scoreboard says what that means and who serves next.
#pragma once

#include <array>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace olympics::sports::racket {

class Scoreboard {
 public:
  virtual ~Scoreboard() = default;
  virtual void point_won(int team) = 0;
  bool over() const { return winner_ >= 0; }
  int winner() const { return winner_; }  // -1 until over
  // The team that serves the next point (in this project: the team the point's first ball is
  // fed to, which plays the first shot).
  virtual int server() const = 0;
  // Per team, the figure stored as the match score (tennis: sets; table tennis: games).
  virtual std::array<float, 2> scores() const = 0;
  // Which team is ahead, comparing sets, games, then points (-1: level): decides a match cut
  // short by its time limit.
  virtual int leader() const = 0;
  virtual std::string text() const = 0;  // "6-4 2-1 30-15"
  virtual nlohmann::json to_json() const = 0;
  int points_played() const { return points_played_; }

 protected:
  int points_played_ = 0;
  int winner_ = -1;
};

struct TennisFormat {
  int sets_to_win = 1;         // best of 1, 3 (2) or 5 (3)
  int games_per_set = 6;       // a set is won at this many games, by 2; tie-break at games-games
  int tiebreak_points = 7;     // a tie-break game is won at this many points, by 2
  bool tiebreak_only = false;  // every set is a single tie-break game (quick training matches)
};

class TennisScore : public Scoreboard {
 public:
  TennisScore(const TennisFormat& format, int first_server);
  void point_won(int team) override;
  int server() const override;
  std::array<float, 2> scores() const override;
  int leader() const override;
  std::string text() const override;
  nlohmann::json to_json() const override;

  bool in_tiebreak() const;
  const std::array<int, 2>& points() const { return points_; }
  const std::array<int, 2>& games() const { return games_; }
  const std::array<int, 2>& sets() const { return sets_; }

 private:
  void game_won(int team);
  TennisFormat format_;
  int game_server_;  // serves the current game (the first point of a tie-break)
  std::array<int, 2> points_{}, games_{}, sets_{};
  std::vector<std::array<int, 2>> finished_sets_;
};

struct TableTennisFormat {
  int games_to_win = 1;  // best of 1, 3 (2), 5 (3), 7 (4)
  int points_per_game = 11;
};

class TableTennisScore : public Scoreboard {
 public:
  TableTennisScore(const TableTennisFormat& format, int first_server);
  void point_won(int team) override;
  int server() const override;
  std::array<float, 2> scores() const override;
  int leader() const override;
  std::string text() const override;
  nlohmann::json to_json() const override;
  const std::array<int, 2>& points() const { return points_; }

 private:
  TableTennisFormat format_;
  int game_first_server_;
  std::array<int, 2> points_{}, games_{};
  std::vector<std::array<int, 2>> finished_games_;
};

}  // namespace olympics::sports::racket
