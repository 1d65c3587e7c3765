#include "basketball/basketball_referee.h"

#include <algorithm>

namespace olympics::sports::basketball {
namespace {

constexpr double kCheckBallBehindArc = 0.75;  // m beyond the arc, at the top of the key
constexpr double kUnderBasket = 1.0;          // m in front of the rim's centre

}  // namespace

const char* restart_name(RestartKind kind) {
  switch (kind) {
    case RestartKind::CheckBall:
      return "check_ball";
    case RestartKind::AfterBasket:
      return "after_basket";
    case RestartKind::Centre:
      return "centre";
    case RestartKind::ThrowIn:
      return "throw_in";
  }
  return "?";
}

BasketballReferee::BasketballReferee(const Court& court, const TeamPlayRules& rules,
                                     std::vector<int> slot_teams)
    : court_(court), rules_(rules), slot_teams_(std::move(slot_teams)) {}

Eigen::Vector2d BasketballReferee::check_ball_spot() const {
  return {-(court_.arc_radius + kCheckBallBehindArc), 0};
}

Eigen::Vector2d BasketballReferee::under_basket_spot(int basket) const {
  return court_.from_basket({-kUnderBasket, 0}, basket);
}

Restart BasketballReferee::start(int team, double t) {
  return stop("start", court_.full ? RestartKind::Centre : RestartKind::CheckBall, team, t).restart;
}

Stoppage BasketballReferee::stop(std::string reason, RestartKind kind, int team, double t) {
  Stoppage s;
  s.reason = std::move(reason);
  s.last_touch = last_touch_;
  Restart& r = s.restart;
  r.kind = kind, r.team = team;
  const Eigen::Vector2d rim = court_.rim_centre(attacks(team)).head<2>();
  switch (kind) {
    case RestartKind::CheckBall:  // at the arc, facing the basket
      r.spot = check_ball_spot(), r.facing = (rim - r.spot).normalized();
      break;
    case RestartKind::AfterBasket:  // under it, facing the arc to clear
      r.spot = under_basket_spot(), r.facing = (r.spot - rim).normalized();
      break;
    case RestartKind::Centre:
      r.spot = {court_.centre_x(), 0}, r.facing = (rim - r.spot).normalized();
      break;
    case RestartKind::ThrowIn:  // under the basket it defends, facing the one it attacks
      r.spot = under_basket_spot(1 - attacks(team)), r.facing = (rim - r.spot).normalized();
      break;
  }
  possession_ = team;
  cleared_ = kind != RestartKind::AfterBasket;
  clock_running_ = true;
  clock_since_ = t;
  last_touch_ = -1;  // a basket needs a new touch: the restart itself shoots nothing
  return s;
}

void BasketballReferee::touch(int slot, const Eigen::Vector2d& root, double t) {
  const int side = team(slot);
  if (side != possession_) {  // a steal or a defensive rebound
    possession_ = side;
    cleared_ = court_.full;  // only the half court asks to clear
    clock_running_ = false;
  }
  if (!clock_running_) {  // after a change of possession, or a shot that hit the basket
    clock_running_ = true;
    clock_since_ = t;
  }
  if (!cleared_ && court_.behind_arc(root, attacks(side))) cleared_ = true;
  last_touch_ = slot;
  last_touch_root_ = root;
}

void BasketballReferee::basket_touch() { clock_running_ = false; }

double BasketballReferee::shot_clock_left(double t) const {
  if (!clock_running_) return rules_.shot_clock_s;
  return std::max(0.0, rules_.shot_clock_s - (t - clock_since_));
}

int BasketballReferee::winner() const {
  for (int side = 0; side < 2; ++side)
    if (score_[side] >= rules_.points_to_win) return side;
  return -1;
}

std::optional<Stoppage> BasketballReferee::full_court_basket(int basket_index, double t) {
  BasketCall call;
  call.team = basket_index;  // the side attacking it
  call.shooter = last_touch_;
  call.release = last_touch_root_;
  call.counted = true;
  call.points = last_touch_ >= 0 && court_.behind_arc(last_touch_root_, basket_index) ? 3 : 2;
  score_[call.team] += call.points;
  Stoppage s = stop("basket", RestartKind::ThrowIn, other(call.team), t);
  s.basket = call;
  return s;
}

Stoppage BasketballReferee::from_below(double t) {
  const int touched = last_touch_ >= 0 ? team(last_touch_) : possession_;
  return stop("from_below", court_.full ? RestartKind::ThrowIn : RestartKind::CheckBall,
              other(touched), t);
}

std::optional<Stoppage> BasketballReferee::update(bool basket, bool out, double t,
                                                  int basket_index) {
  const RestartKind restart = court_.full ? RestartKind::ThrowIn : RestartKind::CheckBall;
  if (basket && court_.full) return full_court_basket(basket_index, t);
  if (basket) {
    BasketCall call;
    call.shooter = last_touch_;
    call.release = last_touch_root_;
    if (last_touch_ >= 0) {
      call.team = team(last_touch_);
      call.counted = cleared_ && possession_ == call.team;
      call.points = call.counted ? (court_.behind_arc(last_touch_root_) ? 2 : 1) : 0;
    }
    if (call.counted) {
      score_[call.team] += call.points;
      Stoppage s = stop("basket", RestartKind::AfterBasket, other(call.team), t);
      s.basket = call;
      return s;
    }
    const int taking = call.team >= 0 ? other(call.team) : other(possession_);
    Stoppage s = stop("not_cleared", restart, taking, t);
    s.basket = call;
    return s;
  }
  if (out) {
    const int touched = last_touch_ >= 0 ? team(last_touch_) : possession_;
    return stop("out", restart, other(touched), t);
  }
  if (clock_running_ && t - clock_since_ >= rules_.shot_clock_s)
    return stop("shot_clock", restart, other(possession_), t);
  return std::nullopt;
}

}  // namespace olympics::sports::basketball
