#include "racket/rally_referee.h"

#include <algorithm>
#include <cmath>

namespace olympics::sports::racket {

RallyReferee::RallyReferee(const RacketGame& game, std::vector<int> slot_teams, bool doubles,
                           bool alternate_hitters)
    : game_(game),
      teams_(std::move(slot_teams)),
      doubles_(doubles),
      alternate_(alternate_hitters) {}

void RallyReferee::start_point(int receiving_team, int first_hitter, double time) {
  striker_ = 1 - receiving_team;
  last_hitter_ = -1;
  last_hit_time_ = -1;
  bounces_ = 0;
  netted_ = false;
  next_hitter_.assign(2, -1);
  if (alternate_) next_hitter_[receiving_team] = first_hitter;
  stall_.restart(time);
  run_surface_ = -1;
  run_last_ = -1;
  call_.reset();
  strokes_ = 0;
  events_ = nlohmann::json::array();
  phase_ = Phase::Rally;
  replay_ = Replay::None;
}

void RallyReferee::start_serve(int serving_team, const ServeRule& rule, double time) {
  // Until the serve is struck the serving team is the side to play, as if the receivers had
  // played the ball to it.
  start_point(serving_team, rule.server_slot, time);
  phase_ = Phase::Toss;
  rule_ = rule;
  toss_time_ = time;
  serve_own_bounce_ = false;
  event("toss", time, rule.server_slot);
}

void RallyReferee::fault(const std::string& detail, double time) {
  if (decided()) return;
  event("fault", time, rule_.server_slot);
  events_.back()["reason"] = detail;
  const int server_team = teams_[rule_.server_slot];
  if (game_.on_table) return lose(server_team, rule_.server_slot, "fault");
  if (rule_.second_serve) return lose(server_team, rule_.server_slot, "double_fault");
  replay_ = Replay::Fault;
}

bool RallyReferee::behind_end_line(int team, const Eigen::Vector3d& ball) const {
  return ball.x() * RacketGame::side_sign(team) > game_.half_length &&
         ball.z() > game_.surface_height;
}

bool RallyReferee::in_service_area(int team, const Eigen::Vector3d& where, int y_sign) const {
  if (!game_.in_half(team, where.x(), where.y(), doubles_)) return false;
  const double r = game_.ball.radius;  // a ball touching a line is in
  if (y_sign != 0 && where.y() * y_sign < -r) return false;
  if (game_.on_table) return true;
  // Tennis: the box between the net and the service line, within the singles sidelines.
  return std::abs(where.x()) <= game_.service_line + r &&
         std::abs(where.y()) <= game_.half_width_singles + r;
}

void RallyReferee::event(const char* name, double time, int slot) {
  nlohmann::json e = {{"call", name}, {"t", std::round(time * 1000) / 1000}};
  if (slot >= 0) e["slot"] = slot;
  events_.push_back(std::move(e));
}

void RallyReferee::lose(int team, int culprit, const std::string& reason) {
  if (decided()) return;
  // Ball return has one team: the point is lost to the launcher, which is no team.
  const bool two_teams = std::find(teams_.begin(), teams_.end(), 1) != teams_.end();
  const int winner = two_teams ? 1 - team : -1;
  call_ = PointCall{winner, team, culprit, reason};
  nlohmann::json e = {
      {"call", "point"}, {"winner_team", winner}, {"reason", reason}, {"strokes", strokes_}};
  if (culprit >= 0) e["culprit_slot"] = culprit;
  events_.push_back(std::move(e));
}

void RallyReferee::concede(int team, int culprit, const std::string& reason) {
  replay_ = Replay::None;
  lose(team, culprit, reason);
}

void RallyReferee::let(const std::string& reason, double time) {
  if (call_) return;
  event("let", time);
  events_.back()["reason"] = reason;
  replay_ = Replay::Let;
}

void RallyReferee::racket_hit(int slot, double time, const Eigen::Vector3d& ball) {
  if (decided()) return;
  const int team = teams_[slot];
  if (slot == last_hitter_ && time - last_hit_time_ < kSameStrokeS) {
    last_hit_time_ = time;  // the ball still on the strings: one stroke
    stall_.restart(time);
    return;
  }
  event("hit", time, slot);
  ++strokes_;
  if (phase_ == Phase::Toss) {
    if (slot != rule_.server_slot) return lose(team, slot, "wrong_hitter");
    if (game_.on_table && !behind_end_line(team, ball)) return fault("struck_over_table", time);
    phase_ = Phase::Served;
  } else {
    if (team == striker_) return lose(team, slot, "double_hit");
    // The serve must bounce on the receiver's side before the receiver plays it.
    if (phase_ == Phase::Served || (game_.on_table && bounces_ == 0))
      return lose(team, slot, "volley");
    if (alternate_ && next_hitter_[team] >= 0 && next_hitter_[team] != slot)
      return lose(team, slot, "wrong_hitter");
  }
  if (alternate_) {
    for (int partner = 0; partner < static_cast<int>(teams_.size()); ++partner)
      if (teams_[partner] == team && partner != slot) next_hitter_[team] = partner;
  }
  striker_ = team;
  last_hitter_ = slot;
  last_hit_time_ = time;
  stall_.restart(time);
  bounces_ = 0;
  netted_ = false;
  run_surface_ = -1;
}

void RallyReferee::surface_contact(ArenaSurface surface, const Eigen::Vector3d& where,
                                   double time) {
  if (decided()) return;
  if (phase_ == Phase::Toss) return fault("not_struck", time);  // the toss fell: no serve
  const bool continuing = surface == run_surface_ && time - run_last_ < kRollingGapS;
  run_last_ = time;
  if (continuing) {
    if (time - run_start_ < kDeadBallS) return;
    run_start_ = time;  // the ball stopped here: it counts as bouncing again, where it lies
    if (surface == kNet)
      return phase_ == Phase::Served ? fault("net", time) : lose(striker_, last_hitter_, "net");
    event("dead_ball", time);
    return phase_ == Phase::Served ? serve_bounce(surface, where, time)
                                   : bounce(surface, where, time);
  }
  run_surface_ = surface;
  run_start_ = time;
  if (surface == kNet) {
    if (!netted_) event("net", time);
    netted_ = true;
    return;
  }
  if (phase_ == Phase::Served) return serve_bounce(surface, where, time);
  bounce(surface, where, time);
}

void RallyReferee::serve_bounce(ArenaSurface surface, const Eigen::Vector3d& where, double time) {
  const int server = striker_, receiver = 1 - striker_;
  const bool on_play_surface = (surface == kTable) == game_.on_table;
  event(on_play_surface ? "bounce" : "floor", time);
  events_.back()["x"] = std::round(where.x() * 100) / 100;
  events_.back()["y"] = std::round(where.y() * 100) / 100;
  const bool own_half = where.x() * RacketGame::side_sign(server) > 0;
  if (game_.on_table && !serve_own_bounce_) {
    // Table tennis: first on the server's own court (doubles: its right half).
    if (on_play_surface && in_service_area(server, where, -rule_.receiver_y_sign)) {
      serve_own_bounce_ = true;
      return;
    }
    return fault("no_bounce_on_own_court", time);
  }
  if (on_play_surface && in_service_area(receiver, where, rule_.receiver_y_sign)) {
    if (netted_) {  // it touched the net and landed in: a let, served again
      event("let", time, rule_.server_slot);
      events_.back()["reason"] = "net_serve";
      replay_ = Replay::Let;
      return;
    }
    phase_ = Phase::Rally;  // a good serve: the receiver must return it
    bounces_ = 1;
    event("serve_in", time, rule_.server_slot);
    return;
  }
  fault(on_play_surface && own_half ? (netted_ ? "net" : "not_over") : "out", time);
}

void RallyReferee::bounce(ArenaSurface surface, const Eigen::Vector3d& where, double time) {
  const int receiver = 1 - striker_;
  const bool on_play_surface = (surface == kTable) == game_.on_table;
  event(on_play_surface ? "bounce" : "floor", time);
  events_.back()["x"] = std::round(where.x() * 100) / 100;
  events_.back()["y"] = std::round(where.y() * 100) / 100;
  if (bounces_ >= 1) return lose(receiver, -1, on_play_surface ? "double_bounce" : "missed");
  if (on_play_surface && game_.in_half(receiver, where.x(), where.y(), doubles_)) {
    bounces_ = 1;
    return;
  }
  // The stroke did not land in: short of the net, or outside the lines (or off the table).
  const bool own_half =
      where.x() * RacketGame::side_sign(striker_) > 0 && std::abs(where.x()) <= game_.half_length;
  const char* reason = own_half ? (netted_ ? "net" : "not_over") : "out";
  lose(striker_, last_hitter_, reason);
}

void RallyReferee::body_touch(int slot, double time) {
  if (decided()) return;
  event("body_touch", time, slot);
  lose(teams_[slot], slot, "body_touch");
}

void RallyReferee::check_stall(double time, double max_rally_s) {
  if (phase_ == Phase::Toss && time - toss_time_ > rule_.limit_s) return fault("not_struck", time);
  stall_.set_limit(max_rally_s);
  if (decided() || !stall_.expired(time)) return;
  lose(1 - striker_, -1, "stalled");
}

}  // namespace olympics::sports::racket
