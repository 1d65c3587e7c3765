// The rules of team play (1v1, 2v2), without physics: the referee is told who touched the ball
// (and where that player stood), when the ball hit the basket (rim, bracket or board), whether
// it went in, whether it touched the floor outside the lines, and says when play stops and how
// it restarts. On the half court (the default) the rules are FIBA 3x3's:
//
// - Possession: the side of the last player to touch the ball. A touch by the other side (a
//   steal, a defensive rebound) changes it, and the new side must clear the ball: a touch by
//   one of its players standing (root) behind the arc. After an offensive rebound it need not.
// - A basket (Court::basket_through) counts for the shooter's side (the last to touch it) when that
// side
//   had cleared: 2 points if the shooter stood behind the arc when it last touched the ball (the
//   release), 1 inside. The other side then takes the ball under the basket and must clear it.
//   A basket by a side that had not cleared does not count (a "not_cleared" violation): the
//   other side's check ball.
// - Shot clock: `shot_clock_s` from each change of possession or restart; the ball hitting the
//   basket stops it, the next touch starts it again. When it runs out: the other side's check
//   ball.
// - The ball on the floor outside the lines: the other side's check ball (the side that did not
//   touch it last). So too the ball passing up through the rim from below (FIBA art. 16: a
//   violation, never a basket; BasketWatch follows it back down so that it cannot count).
// - Check ball: at the top of the arc, already cleared. The game ends when a side reaches
//   `points_to_win`; the match's time limit is the game's clock.
//
// On the full court (Court::full) the rules are the full game's instead: side 0 attacks basket 0
// and side 1 basket 1; a basket counts for the side attacking it, 3 points where the shooter
// stood behind that basket's arc at the release, 2 inside; nothing needs clearing; play starts
// at the centre, and every restart (after a basket, out of bounds, the shot clock) is the
// other side's throw-in under the basket it defends. The shot clock works as above.
// Not enforced (docs/basketball.md): travelling, double dribble, fouls, a player out of bounds,
// backcourt.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "basketball/court.h"

namespace olympics::sports::basketball {

struct TeamPlayRules {
  double shot_clock_s = 12;
  int points_to_win = 21;
};

enum class RestartKind { CheckBall, AfterBasket, Centre, ThrowIn };
const char* restart_name(RestartKind kind);

struct Restart {
  RestartKind kind = RestartKind::CheckBall;
  int team = 0;                                    // the side that takes it
  Eigen::Vector2d spot = Eigen::Vector2d::Zero();  // where its taker stands
  Eigen::Vector2d facing{1, 0};                    // which way it faces (unit, floor)
};

struct BasketCall {
  int team = -1;     // the shooter's side
  int shooter = -1;  // slot of the last touch (-1: nobody touched it since the restart)
  int points = 0;    // 0 when it did not count
  bool counted = false;
  Eigen::Vector2d release = Eigen::Vector2d::Zero();  // the shooter's root at its last touch
};

// Why play stopped this tick, and how it restarts.
struct Stoppage {
  std::string reason;  // "basket", "not_cleared", "out", "shot_clock", "from_below"
  std::optional<BasketCall> basket;
  int last_touch = -1;  // slot
  Restart restart;
};

class BasketballReferee {
 public:
  BasketballReferee(const Court& court, const TeamPlayRules& rules, std::vector<int> slot_teams);

  // The first check ball, by `team`.
  Restart start(int team, double t);
  // A player touched the ball, standing with its root at `root` (may be called many times per
  // tick).
  void touch(int slot, const Eigen::Vector2d& root, double t);
  // The ball hit the rim, its bracket or the board: a shot attempt, the shot clock stops.
  void basket_touch();
  // After each tick: did the ball go down through a rim (which: `basket_index`), did it touch
  // the floor outside the lines. A stoppage, if play stopped.
  std::optional<Stoppage> update(bool basket, bool out, double t, int basket_index = 0);
  // The ball went up through a rim from below (FIBA art. 16): a violation, no basket; the
  // other side's ball (the side that did not touch it last), as after the ball out.
  Stoppage from_below(double t);
  // The basket `team` attacks (0 on the half court).
  int attacks(int team) const { return court_.full ? team : 0; }

  int possession() const { return possession_; }  // the side with the ball (-1: none yet)
  bool cleared() const { return cleared_; }
  bool shot_clock_running() const { return clock_running_; }
  double shot_clock_left(double t) const;
  const std::array<int, 2>& score() const { return score_; }
  // The side that reached points_to_win, else -1.
  int winner() const;
  int last_touch() const { return last_touch_; }
  // Where the restarts are taken: at the arc, and under `basket`.
  Eigen::Vector2d check_ball_spot() const;
  Eigen::Vector2d under_basket_spot(int basket = 0) const;

 private:
  Stoppage stop(std::string reason, RestartKind kind, int team, double t);
  std::optional<Stoppage> full_court_basket(int basket_index, double t);
  int team(int slot) const { return slot_teams_[slot]; }
  int other(int team) const { return 1 - team; }

  Court court_;
  TeamPlayRules rules_;
  std::vector<int> slot_teams_;
  std::array<int, 2> score_{};
  int possession_ = -1;
  bool cleared_ = false;
  bool clock_running_ = false;
  double clock_since_ = 0;
  int last_touch_ = -1;
  Eigen::Vector2d last_touch_root_ = Eigen::Vector2d::Zero();
};

}  // namespace olympics::sports::basketball
