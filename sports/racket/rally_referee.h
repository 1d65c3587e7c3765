// The referee of one rally in tennis or table tennis: it is told what the ball touched (a
// racket, the ground, the table, the net, a body) and calls the point by the rules (SPORTS.md):
//
// - after a team strikes, the ball must first bounce in the other team's half (tennis: on the
//   ground inside the lines; table tennis: on the table); touching the net on the way is fine;
// - the receiving team must strike before the ball bounces twice (table tennis: after exactly one
//   bounce on the table, never before), and only once per crossing (no double hits);
// - a ball that touches a player's body loses the point for that player's team;
// - table-tennis doubles: partners strike alternately;
// - a ball that stops (rolls or rests for 0.3 s) counts as bounced again where it lies.
//
// Each point starts with a ball fed towards one team, which plays the first shot (the feed
// counts as the other team's stroke), or (`start: "serve"`) with a ball tossed for the server,
// which must serve it legally (start_serve). The referee keeps no physics: it is tested with
// made-up sequences of touches.
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "framework/stall_timer.h"
#include "racket/racket_game.h"

namespace olympics::sports::racket {

struct PointCall {
  int winner_team = -1;
  int loser_team = -1;
  int culprit_slot = -1;  // the player whose action lost it, when one did
  std::string reason;     // "out", "net", "double_bounce", "body_touch", ...
};

// A served point: who serves and where the serve must land (the match decides it from the score).
struct ServeRule {
  int server_slot = 0;
  // The y sign (world frame) of the receiver's service box (tennis) or half of the table (table
  // tennis doubles: the server's own bounce is then on the other y side, right half to right
  // half); 0: the whole half (table-tennis singles).
  int receiver_y_sign = 0;
  bool second_serve = false;  // tennis: a fault now loses the point (table tennis: every fault)
  double limit_s = 3;         // the toss not struck within this long: a fault
};

class RallyReferee {
 public:
  // slot_teams: team of each slot; 2v2 table tennis sets alternate_hitters.
  RallyReferee(const RacketGame& game, std::vector<int> slot_teams, bool doubles,
               bool alternate_hitters);

  // A new point: the ball is fed towards `receiving_team`; `first_hitter` is the slot expected to
  // play it when partners alternate (-1: either).
  void start_point(int receiving_team, int first_hitter, double time);
  // A new served point: the ball is tossed for `rule.server_slot` of `serving_team`. The serve
  // must be struck before the toss touches anything and within rule.limit_s; tennis: it must
  // first bounce in the diagonal service box (ITF rules 8-11); table tennis: on the server's
  // court, then over the net onto the receiver's (ITTF 2.6, 2.7). A fault (tennis' first, or a
  // net cord that lands in: a let) asks for the serve again (replay()); otherwise the point is
  // lost ("double_fault" in tennis, "fault" in table tennis).
  void start_serve(int serving_team, const ServeRule& rule, double time);
  enum class Replay { None, Fault, Let };
  // The serve is to be taken again (the match tosses a new ball); nothing more is called till then.
  Replay replay() const { return replay_; }
  bool serving() const { return phase_ != Phase::Rally; }  // the serve has not landed in yet

  // The ball touched something at `time` (seconds since the match began); `ball` is its centre.
  // A table-tennis serve must be struck behind the server's end line and above the table's
  // surface (ITTF 2.6.4): a fault otherwise ("struck_over_table").
  void racket_hit(int slot, double time, const Eigen::Vector3d& ball);
  void surface_contact(ArenaSurface surface, const Eigen::Vector3d& where, double time);
  void body_touch(int slot, double time);
  // `team` loses the point for a reason found outside the ball's touches (a fall). It overrules
  // a fault or a let called since the last toss (the match concedes a tick's falls before it
  // tosses again): the ball was in play when the player fell.
  void concede(int team, int culprit, const std::string& reason);
  // The point is to be played again (both sides fell at once): a let, even over a fault called
  // since the last toss; replay() tells the match to toss again.
  void let(const std::string& reason, double time);
  // No stroke and no decision for this long: the team that had to play the ball loses
  // ("stalled"), e.g. a ball stuck where nobody reaches it.
  void check_stall(double time, double max_rally_s);

  const std::optional<PointCall>& call() const { return call_; }
  int striker_team() const { return striker_; }
  int receiver_team() const { return 1 - striker_; }
  int last_hitter() const { return last_hitter_; }  // -1: none this crossing (the feed)
  int strokes() const { return strokes_; }          // this point's strokes so far, both sides
  int bounces() const { return bounces_; }          // on the receiver's side since the last stroke
  bool netted() const { return netted_; }
  // The referee's calls so far this point (hit, bounce, net, ...), for the match's info.
  const nlohmann::json& events() const { return events_; }

  static constexpr double kSameStrokeS = 0.15;  // racket contacts closer than this are one stroke
  static constexpr double kRollingGapS = 0.05;  // contacts closer than this are one contact
  static constexpr double kDeadBallS = 0.3;     // continuous contact this long: the ball stopped

 private:
  void bounce(ArenaSurface surface, const Eigen::Vector3d& where, double time);
  void serve_bounce(ArenaSurface surface, const Eigen::Vector3d& where, double time);
  bool in_service_area(int team, const Eigen::Vector3d& where, int y_sign) const;
  bool behind_end_line(int team, const Eigen::Vector3d& ball) const;  // table tennis serve
  void fault(const std::string& detail, double time);
  bool decided() const { return call_ || replay_ != Replay::None; }
  void lose(int team, int culprit, const std::string& reason);
  void event(const char* name, double time, int slot = -1);

  RacketGame game_;
  std::vector<int> teams_;
  bool doubles_, alternate_;
  int striker_ = 0;
  int last_hitter_ = -1;
  double last_hit_time_ = -1;
  int bounces_ = 0;
  int strokes_ = 0;  // this point's strokes, both sides (the point call reports them)
  bool netted_ = false;
  std::vector<int> next_hitter_;  // per team, when partners alternate (-1: either)
  StallTimer stall_;              // since the point began or the last stroke
  // The current run of contacts with one surface (rolling / resting).
  int run_surface_ = -1;
  double run_start_ = 0, run_last_ = -1;
  std::optional<PointCall> call_;
  // The serve: tossed, struck (till it lands in), or the rally under way.
  enum class Phase { Rally, Toss, Served };
  Phase phase_ = Phase::Rally;
  ServeRule rule_;
  double toss_time_ = 0;
  bool serve_own_bounce_ = false;  // table tennis: the serve has bounced on the server's court
  Replay replay_ = Replay::None;
  nlohmann::json events_ = nlohmann::json::array();
};

}  // namespace olympics::sports::racket
