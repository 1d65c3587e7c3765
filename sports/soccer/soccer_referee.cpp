#include "soccer/soccer_referee.h"

#include <algorithm>
#include <cmath>

namespace olympics::sports::soccer {

const char* restart_name(RestartKind kind) {
  switch (kind) {
    case RestartKind::KickOff:
      return "kick_off";
    case RestartKind::ThrowIn:
      return "throw_in";
    case RestartKind::FreeKick:
      return "free_kick";
    case RestartKind::GoalKick:
      return "goal_kick";
    case RestartKind::Corner:
      return "corner";
  }
  return "?";
}

SoccerReferee::SoccerReferee(const Field& field, const SoccerRules& rules,
                             std::vector<int> slot_teams, double ball_radius)
    : field_(field), rules_(rules), slot_teams_(std::move(slot_teams)), ball_radius_(ball_radius) {}

void SoccerReferee::start(int team, double t) {
  first_kick_off_ = team;
  pending_ = Restart{RestartKind::KickOff, team, {0, 0}};
  pending_since_ = t;
}

int SoccerReferee::attack_direction(int team) const {
  const int first_half = team == 0 ? 1 : -1;
  return half_ % 2 == 0 ? first_half : -first_half;
}

void SoccerReferee::touch(int slot, double) {
  if (pending_) {
    if (team(slot) != pending_->team) {
      if (encroacher_ < 0) encroacher_ = slot;
      return;
    }
    pending_.reset();  // played by the side that takes it: in play
  }
  if (slot == last_touch_) return;
  touch_before_ = last_touch_;
  last_touch_ = slot;
}

Stoppage SoccerReferee::stop(std::string reason, const Restart& next, double t) {
  Stoppage s;
  s.reason = std::move(reason);
  s.last_touch = last_touch_;
  s.restart = next;
  pending_ = next;
  pending_since_ = t;
  encroacher_ = -1;
  last_touch_ = touch_before_ = -1;
  return s;
}

std::optional<Stoppage> SoccerReferee::update(const Eigen::Vector3d& ball, double t) {
  if (encroacher_ >= 0 && pending_) {
    const int culprit = encroacher_;
    Stoppage s = stop("encroachment", *pending_, t);
    s.culprit = culprit;
    return s;
  }
  if (half_ + 1 < rules_.halves && t >= rules_.half_s * (half_ + 1) - 1e-9) {
    ++half_;
    const int team = half_ % 2 == 0 ? first_kick_off_ : 1 - first_kick_off_;
    return stop("half_time", {RestartKind::KickOff, team, {0, 0}}, t);
  }
  if (pending_ && t - pending_since_ >= rules_.restart_timeout_s) pending_.reset();

  int end = 0;
  const Crossed crossed = field_.crossed(ball, ball_radius_, &end);
  if (crossed == Crossed::None) return std::nullopt;
  const int last_team = last_touch_ >= 0 ? team(last_touch_) : -1;
  if (crossed == Crossed::Goal) {
    GoalCall g;
    g.team = attack_direction(0) == end ? 0 : 1;
    g.scorer = last_touch_;
    g.own_goal = last_team >= 0 && last_team != g.team;
    if (!g.own_goal && touch_before_ >= 0 && team(touch_before_) == g.team)
      g.assist = touch_before_;
    ++score_[g.team];
    Stoppage s = stop("goal", {RestartKind::KickOff, 1 - g.team, {0, 0}}, t);
    s.goal = g;
    return s;
  }
  const double r = ball_radius_;
  if (crossed == Crossed::TouchLine) {
    // Nobody touched it (a restart that rolled out untouched cannot happen): team 0 restarts.
    const int team_to_take = last_team >= 0 ? 1 - last_team : 0;
    const double side = ball.y() > 0 ? 1 : -1;
    const double x = std::clamp(ball.x(), -field_.half_length() + r, field_.half_length() - r);
    const double inside = rules_.touch_free_kick ? 1.0 : r;
    Stoppage s = stop("out",
                      {rules_.touch_free_kick ? RestartKind::FreeKick : RestartKind::ThrowIn,
                       team_to_take,
                       {x, side * (field_.half_width() - inside)}},
                      t);
    s.line = "touch";
    return s;
  }
  // Over a goal line, wide of the goal or over the bar.
  const int attackers = attack_direction(0) == end ? 0 : 1;
  Restart next;
  if (last_team == attackers || last_team < 0) {
    next = {
        RestartKind::GoalKick, 1 - attackers, {end * (field_.half_length() - Field::kGoalArea), 0}};
  } else {
    const double side = ball.y() > 0 ? 1 : -1;
    next = {RestartKind::Corner,
            attackers,
            {end * (field_.half_length() - r), side * (field_.half_width() - r)}};
  }
  Stoppage s = stop("out", next, t);
  s.line = "goal";
  return s;
}

}  // namespace olympics::sports::soccer
