// The rules of team play (1v1, 2v2), without physics: the referee is told who touched the ball
// and where the ball is after each tick, and says when play stops and how it restarts.
//
// - Goal: the whole ball over a goal line between the posts and under the bar (Field::crossed);
//   the scorer is the last player to touch it (an own goal when that player defends this goal);
//   the assist, a teammate who touched it just before the scorer. Kick-off by the conceding team.
// - The whole ball over a touch line: a throw-in (or, as a setting, a free kick) for the side
//   that did not touch it last, where it left the field.
// - Over a goal line outside the goal: a goal kick when the attackers touched it last, a corner
//   when the defenders did.
// - A restart waits for the taking side to play the ball: if an opponent touches it first, the
//   restart is taken again (an encroachment); after `restart_timeout_s` the ball is in play anyway.
// - Halves: at half-time the teams change ends and the side that did not kick off first kicks
//   off. The time limit (all halves) ends the match; the match decides who won.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "soccer/field.h"

namespace olympics::sports::soccer {

struct SoccerRules {
  int halves = 2;
  double half_s = 120;
  bool touch_free_kick = false;   // over a touch line: a free kick instead of a throw-in
  double restart_distance = 3.0;  // m: opponents kept this far from a restart (real: 9.15)
  double restart_timeout_s = 10;  // a restart nobody takes is in play after this long
};

enum class RestartKind { KickOff, ThrowIn, FreeKick, GoalKick, Corner };
const char* restart_name(RestartKind kind);

struct Restart {
  RestartKind kind = RestartKind::KickOff;
  int team = 0;                                    // the side that takes it
  Eigen::Vector2d spot = Eigen::Vector2d::Zero();  // where the ball is placed
};

struct GoalCall {
  int team = -1;    // the side the goal counts for
  int scorer = -1;  // slot of the last touch (-1: nobody touched it)
  int assist = -1;  // slot of a teammate's touch just before, or -1
  bool own_goal = false;
};

// Why play stopped this tick, and how it restarts.
struct Stoppage {
  std::string reason;  // "goal", "out", "half_time", "encroachment"
  std::optional<GoalCall> goal;
  std::string line;     // out: "touch" or "goal"
  int last_touch = -1;  // slot
  int culprit = -1;     // encroachment: the opponent who touched the ball first
  Restart restart;
};

class SoccerReferee {
 public:
  SoccerReferee(const Field& field, const SoccerRules& rules, std::vector<int> slot_teams,
                double ball_radius);

  // The first kick-off, by `team`.
  void start(int team, double t);
  // A player touched the ball (may be called many times per tick).
  void touch(int slot, double t);
  // After each tick, the ball's centre: a stoppage, if play stopped.
  std::optional<Stoppage> update(const Eigen::Vector3d& ball, double t);

  // +1 when `team` attacks the goal at x = +L/2 in the current half, -1 otherwise.
  int attack_direction(int team) const;
  int half() const { return half_; }
  const std::array<int, 2>& score() const { return score_; }
  // The restart waiting to be taken; nullopt while the ball is in play.
  const std::optional<Restart>& pending() const { return pending_; }
  int last_touch() const { return last_touch_; }

 private:
  Stoppage stop(std::string reason, const Restart& next, double t);
  int team(int slot) const { return slot_teams_[slot]; }

  Field field_;
  SoccerRules rules_;
  std::vector<int> slot_teams_;
  double ball_radius_;
  std::array<int, 2> score_{};
  int half_ = 0;
  int first_kick_off_ = 0;
  std::optional<Restart> pending_;
  double pending_since_ = 0;
  int encroacher_ = -1;
  int last_touch_ = -1;
  int touch_before_ = -1;  // the last touch by another slot than last_touch_
};

}  // namespace olympics::sports::soccer
