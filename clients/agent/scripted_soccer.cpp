#include "scripted_soccer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "control/body_model.h"
#include "scripted_soccer_kick.h"
#include "smpl_observation.h"

namespace olympics::client {
namespace {

Eigen::Vector2d xy(std::span<const float> o, int at) { return {o[at], o[at + 1]}; }

using namespace smpl;

constexpr double kBehind_m = 0.7;      // the approach point, behind the ball
constexpr double kLinedUp_m = 0.35;    // off the ball-to-aim line by less than this: lined up
constexpr double kLoseLine_m = 0.6;    // ...and it stops pushing when further off than this
constexpr double kThrough_m = 0.6;     // while pushing, it walks to this far past the ball
constexpr double kKeepBack_m = 3.8;    // from the ball while the other side restarts
constexpr double kDefend_m = 5.0;      // the second player, this far out from its own goal
constexpr double kDownBelow_m = -0.4;  // a teammate's root this far below mine: it is down
// In a match the chaser kicks (the penalty's kick) a ball this near the goal it attacks, and
// dribbles a ball further out (match seeds 1-12, 2v2: 9 m 4 goals, 11 m 7, 13 m 8 with 2 own
// goals, 16 m 8 with 30% more falls than 11 m, everywhere 5 with twice the falls).
constexpr double kShootFrom_m = 11.0;
// In 2v2 a ball up to kShootPressedFrom_m out is kicked too while an opponent (not down) is within
// kPressedBy_m of it: the opponent keeping off 3 m away took the dribbler's pushes (2v2 tuning
// seeds 1-30: goals 39 (7 own) -> 51 (4 own), falls 171 -> 204; unseen seeds 220001-220048 and
// 230001-230048: 3.02 -> 4.22 goals per 10 minutes, but falls 0.369 -> 0.434 per player-minute,
// the kick's own; docs/soccer.md, "shooting from 15 m when pressed" and "the pressed 15 m shot
// again"). Making those kicks fall less cost their goals (a faster or waited weight shift onto
// the planted foot, a slower ball, a slower start: 2v2 seeds 1-11).
constexpr double kShootPressedFrom_m = 15.0;
constexpr double kPressedBy_m = 4.0;
// An opponent has the ball: I stay this far from the ball, and at least kKeepOffHolder_m from
// the opponent. From 1.5 m (issue 30's third round) the ball changed sides 3.5 times a minute
// in 2v2 (a push toward the holder's goal could bring the ball nearer the yielder, who then
// took it over) and the ball stayed in midfield (the side nearest it was within 11 m of the
// goal it attacks 12% of the time). From 3 m (match tuning seeds 1-9, 31-39, 2v2, 72 minutes):
// 2.4 changes a minute, 17% of the time within 11 m, kicks 51 -> 79, goals 10 -> 13, falls 125
// -> 116. With the aim below, on unseen match seeds 160001-160048: falls 411 -> 335 in 2v2 and
// 389 -> 262 in 1v1 (resolved), goals 23 -> 20 and 55 -> 62 (not resolved); docs/soccer.md.
constexpr double kKeepOffBall_m = 3.0;
constexpr double kKeepOffHolder_m = 1.5;
// An opponent this near the middle of the goal I attack is in the way of a shot at the middle:
// I aim inside the post away from it. 3 m took the penalty keeper (0.5 m out); 6 m takes the 2v2
// guard too (the second player, 5 m out on the line from its goal to the ball, in the way of a
// shot at the middle): an opponent touched 7 of 20 shots on target first (the tuning seeds
// above, with the 3 m keep-off; with 6 m 2 of 18, goals 13 -> 17, falls 116 -> 106).
constexpr double kKeeperNear_m = 6.0;
constexpr double kShotAim_m = 1.3;  // ...and I aim this far off the goal's middle, away
// The kick (penalty modes).
constexpr double kKickFrom_m = 0.12;   // this close to where a kick starts: kick
constexpr double kSettled_mps = 0.45;  // ...walking no faster than this
constexpr double kAtRest_mps = 0.15;   // ...a ball this slow
constexpr double kKickFacing = 0.4;    // ...facing the kick's line within this, rad
// A penalty kick walking in starts only in the sway toward the kicking foot (kKickSway_mps), as a
// match kick (issue 30's penalty sway round, penalty tuning seeds 1-300): main started 74 of 300
// kicks (no keeper) in the other half; 4 of them scored and 73 kickers fell. Waiting for the sway
// at the start point: no keeper 221 -> 288 goals, kickers down 107 -> 65; against the keeper 158 ->
// 192, 137 -> 101. The penalty keeps its own window and pace (with the match's, 25 cm behind and
// 0.6 m/s: 263 and 164 goals, 162 and 201 down); a sway over 0.1 m/s: 285 and 192, 80 and 106.
// Unseen seeds 180101-180500: scored 73.8% -> 94.2% and 50.8% -> 66.8% (docs/soccer.md).
// In a match a kick (the right foot's) starts only with the ball at most this far to the left
// (the planting foot's side) of my root, across the kick's line: further left, the plant step
// went onto or against the ball and the kicker went down before its swing (issue 30's kick,
// fourth round, match tuning seeds 1-30, 2v2: 22 of 37 kicks started with the ball 4 cm or more
// left, 2 of 46 with it to the right). With this, 7 of 91 kicks ended so (26 of 96 before),
// goals 15 -> 18, falls 273 -> 239. Walking the start point 4-6 cm left, or stepping to put the
// ball right of the line, brought the early falls back (17-35 of 91-103 kicks).
constexpr double kMatchKickBallLeft_m = 0.02;
// A kick (a match's since the seventh round, a penalty's walking in since the penalty sway round)
// starts only in the gait's sway toward the kicking (right) foot: the root moving right across
// the kick's line faster than kKickSway_mps. The kick's first phase shifts the weight
// onto the kicking foot; started while the body swayed the other way it fought the sway, the
// plant landed further behind the ball and the kicker fell (issue 30's kick, seventh round,
// match tuning seeds 1-24, 2v2: of 112 kicks, 55 started swaying right: 33 sent the ball over 4
// m/s, 19 goals; 57 not: 10, 3 goals; of 60 penalty kicks 46 and 14: 46 and 4 over 4 m/s).
// Waiting for that half of the step, the kick may start up to kMatchKickFromBehind_m behind its
// start point (not only kKickFrom_m either way) at up to kMatchKickWalk_mps: with the sway
// alone and the window as the penalty's, 95 kicks, goals 25 -> 19; with both, 72 kicks (60 over
// 4 m/s), goals 25 -> 36 (7 own against 3), falls 161 -> 129.
constexpr double kKickSway_mps = 0.05;
constexpr double kMatchKickFromBehind_m = 0.25;
constexpr double kMatchKickFromAhead_m = 0.05;
constexpr double kMatchKickWalk_mps = 0.6;
constexpr double kRolling_mps = 0.5;      // a ball faster than this is followed, not kicked
constexpr double kKnockedAway_mps = 2.5;  // a kick gives up on a ball knocked this fast
constexpr double kDown_m = 0.6;           // ...and on a body whose root is this low
constexpr double kKickerWalk_mps = 0.8;   // a kicker's walking speed (StepGains::max_speed)
constexpr double kKickerWalkPerM = 1.5;   // ...and its StepGains::speed_per_m
constexpr double kMatchWalk_mps = 1.0;    // a player's walking speed in a match
constexpr double kArriveSpeed_mps = 3.0;  // a shot is kicked to be this fast at the goal line
constexpr double kRollingDecel_mps2 =
    2.0;  // a kicked ball slows by about this (slides, then rolls)
constexpr double kMaxShot_mps = 8.0;
constexpr double kKeeperSideSpeed_mps = 1.0;  // a keeper's StepGains::max_side_speed
constexpr double kKeeperSpeedPerM = 4.0;      // ...and its StepGains::speed_per_m
constexpr double kKeeperOut_m = 0.5;          // a keeper stands this far in front of its line
constexpr double kPostInside_m = 1.7;         // ...and no further across than this from the middle
constexpr double kShotComing_mps = 1.0;       // a ball closing on the goal faster than this: a shot
constexpr double kFollowBall = 0.3;  // not a shot: the keeper follows the ball's side by this
// The right foot's kick leaves the ball about 6.5 degrees right of its swing's line (median,
// penalty seeds 1-200): the swing's line is turned this much left of the aim (issue 30's fifth
// round, penalty seeds 1-200, goals without / against the keeper, the kick's ball_per_foot 2.0:
// none 122 / 79, 3 degrees 141 / 105, 4: 134 / 96, 5: 148 / 114, 6: 149 / 102, 7: 141 / 94;
// unturned, a third of the shots at the right post's inside went wide).
constexpr double kKickLineLeft_rad = 5 * M_PI / 180;

double bearing(const Eigen::Vector2d& v) { return std::atan2(v.y(), v.x()); }
// In 2v2 (a teammate seen), whether the ball is within kShootPressedFrom_m of the goal I attack
// with an opponent (not down) within kPressedBy_m of it: then I kick it, not dribble it.
bool pressed_within_shot(const ScriptedSoccerPolicy::View& v) {
  const Eigen::Vector2d ball = v.ball.head<2>();
  if (!v.teammate || (v.goal - ball).norm() >= kShootPressedFrom_m) return false;
  for (std::size_t k = 0; k < v.opponents.size(); ++k)
    if (!v.opponent_down[k] && (v.opponents[k] - ball).norm() < kPressedBy_m) return true;
  return false;
}
Eigen::Vector2d left_of(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }
// Whether the root's horizontal `velocity` sways toward the kicking (right) foot across the
// kick's line `dir` (kKickSway_mps).
bool swaying_toward_kicking_foot(const Eigen::Vector2d& dir, const Eigen::Vector2d& velocity) {
  return left_of(dir).dot(velocity) < -kKickSway_mps;
}

}  // namespace

void ScriptedSoccerPolicy::start(const MatchInfo& match) {
  if (match.sport != "soccer")
    throw std::invalid_argument("the scripted soccer policy plays soccer, not " + match.sport);
  const ObservationLayout& l = match.observation;
  blocks_ = {l.offset("ball", "position"),
             l.offset("ball", "velocity"),
             l.offset("goals", "attack"),
             l.offset("goals", "defend"),
             l.has("teammates") ? l.offset("teammates", "position_0") : -1,
             l.offset("match", "restart"),
             {}};
  for (int k = 0; l.has("opponents", "position_" + std::to_string(k)); ++k)
    blocks_.opponents.push_back(l.offset("opponents", "position_" + std::to_string(k)));
  control_dt_ = match.control_dt;
  keeper_mode_ = match.mode == "penalty_kick_keeper";
  keeper_.reset();
  legs_.reset();
  lined_up_ = false;
  // Penalty kicks are kicked; in matches the chaser kicks within kShootFrom_m of the goal (an
  // opponent keeps off a ball I am nearer, so the kick has time to wind up; in 2v2 within
  // kShootPressedFrom_m while an opponent is near the ball) and dribbles further out.
  penalty_ = match.mode.rfind("penalty_kick", 0) == 0;
  if (!model_)
    model_ = std::make_shared<control::BodyModel>(
        control::BodyModel::humanoid(core::HumanoidKind::Smpl));
  kick_ = std::make_shared<SoccerKick>(*model_, control_dt_);
}

ScriptedSoccerPolicy::View ScriptedSoccerPolicy::see(std::span<const float> o) const {
  const Blocks& at = blocks_;
  View v;
  v.ball = vec3(o, at.ball);
  v.ball_velocity = vec3(o, at.ball_velocity);
  v.goal = xy(o, at.goal);
  v.own_goal = xy(o, at.own_goal);
  if (at.mate >= 0) {
    v.teammate = xy(o, at.mate);
    v.mate_down = vec3(o, at.mate).z() < kDownBelow_m;
  }
  for (int at_opponent : at.opponents) {
    v.opponents.push_back(xy(o, at_opponent));
    v.opponent_down.push_back(vec3(o, at_opponent).z() < kDownBelow_m);
  }
  v.theirs_to_take = o[at.restart] < -0.5;
  return v;
}

void ScriptedSoccerPolicy::walk(std::span<const float> o, const Eigen::Vector2d& to, double turn,
                                std::span<float> a) {
  if (!legs_) {
    StepGains gains;
    gains.turn_start = 0.5;
    if (keeper_ && *keeper_) {
      // A keeper shuffles across its line faster than a walker sidesteps.
      gains.max_side_speed = kKeeperSideSpeed_mps;
      gains.max_speed = kKeeperSideSpeed_mps;
      gains.speed_per_m = kKeeperSpeedPerM;
    } else if (!penalty_) {
      // In a match: slower than the stepping controller's 1.2 m/s, which falls more often
      // (match seeds 1-4: 2v2 falls 2.05 per player-minute at 1.2, 1.66 at 1.0).
      gains.max_speed = kMatchWalk_mps;
    } else {
      // A kicker walks slower: it stops where a kick starts, not a step past it.
      gains.max_speed = kKickerWalk_mps;
      gains.speed_per_m = kKickerWalkPerM;
    }
    legs_.emplace(gains, control_dt_);
  }
  legs_->act(o, to, turn, a);
}

void ScriptedSoccerPolicy::act(std::span<const float> o, std::span<float> a) {
  if (control_dt_ <= 0) throw std::logic_error("ScriptedSoccerPolicy: act() before start()");
  if (a.size() != kActions)
    throw std::invalid_argument("the scripted soccer policy drives the SMPL humanoid (69 actions)");
  std::fill(a.begin(), a.end(), 0.0f);
  const View v = see(o);
  // The keeper is the one whose own goal is near at the start.
  if (!keeper_) keeper_ = keeper_mode_ && v.own_goal.norm() < 3.0;

  if (*keeper_) return doing_ = "keeper", keep_goal(o, v, a);
  // A kick under way is finished (it gives up itself on a ball knocked away or a fall).
  if (kick_->active()) return kick_chase(o, v, a);
  if (v.theirs_to_take) {
    doing_ = "keep_back";
    lined_up_ = false;
    const Eigen::Vector2d ball = v.ball.head<2>();
    const Eigen::Vector2d back = ball + (v.own_goal - ball).normalized() * kKeepBack_m;
    return walk(o, back, bearing(ball), a);
  }
  // One chaser per side: whoever is nearer the ball (each of the two sees the same distances),
  // unless the teammate is down.
  const Eigen::Vector2d ball = v.ball.head<2>();
  const bool chaser = !v.teammate || v.mate_down || ball.norm() < (ball - *v.teammate).norm();
  if (!chaser) {
    doing_ = "support";
    lined_up_ = false;
    const Eigen::Vector2d to_ball = ball - v.own_goal;
    const Eigen::Vector2d guard =
        v.own_goal + to_ball.normalized() * std::min(kDefend_m, 0.5 * to_ball.norm());
    return walk(o, guard, bearing(ball), a);
  }
  if (penalty_) return kick_chase(o, v, a);
  chase(o, v, a);
}

void ScriptedSoccerPolicy::kick_chase(std::span<const float> o, const View& v, std::span<float> a) {
  doing_ = kick_->active() ? "kick" : "shoot_approach";
  const Eigen::Vector2d ball = v.ball.head<2>();
  const double rolling = v.ball_velocity.head<2>().norm();
  const control::BodyPose pose = model_->pose_from_observation(o);
  const Eigen::Vector2d aim = shot_aim(v), to_aim = (aim - ball).normalized();
  const double speed = shot_speed((aim - ball).norm());
  // The kick (always the right foot's) swings along a line turned left of the aim: it pulls the
  // ball to the right of its line.
  const Eigen::Vector2d dir =
      std::cos(kKickLineLeft_rad) * to_aim + std::sin(kKickLineLeft_rad) * left_of(to_aim);

  if (kick_->active()) {
    if ((!kick_->struck() && rolling > kKnockedAway_mps) || root_height(o) < kDown_m) {
      kick_->abort();
      legs_.reset();
    } else {
      if (!kick_->struck()) kick_direction_ = dir, kick_speed_ = speed;
      kick_->act(o, pose, v.ball, kick_direction_, kick_speed_, a);
      if (!kick_->active()) {
        // The kicking foot is still in the air: the stepping controller takes over with it as
        // its first swing foot (it swings the foot on its target's side).
        legs_.reset();
        std::fill(a.begin(), a.end(), 0.0f);
        walk(o, Eigen::Vector2d(0.3, kick_->right_foot() ? -0.3 : 0.3), 0, a);
      }
      return;
    }
  }
  if (rolling > kRolling_mps) {
    // Follow it: to where it is going, behind it on the line to the aim.
    const Eigen::Vector2d ahead = ball + v.ball_velocity.head<2>() * 0.5;
    return walk(o, ahead - dir * 0.8, bearing(ahead), a);
  }
  // At the kick's start, standing or nearly (both feet down, slow, under the body): kick.
  const Eigen::Vector2d start = ball + kick_->approach_from_ball(dir, true);
  const double ground = -root_height(o);
  const Eigen::Vector3d com = model_->centre_of_mass(pose);
  auto under_body = [&](int ankle) {
    const Eigen::Vector3d at = body_position(o, ankle);
    const double ahead = (at - com).head<2>().dot(dir);
    return at.z() < ground + 0.1 && ahead > -0.15 && ahead < 0.12;
  };
  const Eigen::Vector3d velocity = root_velocity(o);
  const bool stepping = legs_ && legs_->stepping();
  // The ball-side rule is the match's (a penalty's ball lies where the kick's start point puts it:
  // not measured there); the start's sway gate is both's.
  const bool ball_on_kicking_side = penalty_ || left_of(dir).dot(ball) <= kMatchKickBallLeft_m;
  const bool ready = penalty_ ? at_penalty_kick_start(start, dir, stepping, velocity)
                              : at_match_kick_start(start, dir, stepping, velocity.head<2>());
  if (ready && under_body(kLAnkle) && under_body(kRAnkle) && rolling < kAtRest_mps &&
      std::abs(bearing(dir)) < kKickFacing && ball_on_kicking_side) {
    kick_->start(true);
    doing_ = "kick";
    kick_direction_ = dir, kick_speed_ = speed;
    kick_->act(o, pose, v.ball, kick_direction_, kick_speed_, a);
    return;
  }
  const Eigen::Vector2d me = -ball;  // my root, relative to the ball
  Eigen::Vector2d target = start;
  if (me.dot(dir) > -0.3 && std::abs(left_of(dir).dot(me)) < 0.9) {
    // On the wrong side of the ball, or too close beside it: round it, on my side of the line.
    const double side = left_of(dir).dot(me) >= 0 ? 1 : -1;
    target = ball - dir * 0.9 + left_of(dir) * side * 1.0;
  }
  walk(o, target, bearing(target.norm() > 1.0 ? target : dir), a);
}

bool ScriptedSoccerPolicy::at_penalty_kick_start(const Eigen::Vector2d& start,
                                                 const Eigen::Vector2d& dir, bool stepping,
                                                 const Eigen::Vector3d& velocity) {
  if (start.norm() >= kKickFrom_m) return false;
  if (!stepping) return true;
  // Walking: slowly, and in the sway toward the kicking foot, as a match kick (its whole speed,
  // vertical part included, as the fifth round chose it; the sway across the kick's line).
  return velocity.norm() < kSettled_mps && swaying_toward_kicking_foot(dir, velocity.head<2>());
}

bool ScriptedSoccerPolicy::at_match_kick_start(const Eigen::Vector2d& start,
                                               const Eigen::Vector2d& dir, bool stepping,
                                               const Eigen::Vector2d& velocity) {
  const double behind = start.dot(dir);  // how far the root is behind the start point
  return behind < kMatchKickFromBehind_m && behind > -kMatchKickFromAhead_m &&
         std::abs(left_of(dir).dot(start)) < kKickFrom_m &&
         (!stepping || velocity.norm() < kMatchKickWalk_mps) &&
         swaying_toward_kicking_foot(dir, velocity);
}

Eigen::Vector2d ScriptedSoccerPolicy::shot_aim(const View& v) {
  // The goal's middle, or with a keeper there, inside the post away from it.
  const Eigen::Vector2d across = left_of((v.goal - v.own_goal).normalized());
  Eigen::Vector2d aim = v.goal;
  for (const Eigen::Vector2d& p : v.opponents)
    if ((p - v.goal).norm() < kKeeperNear_m)
      aim = v.goal - across * kShotAim_m * ((p - v.goal).dot(across) >= 0 ? 1 : -1);
  return aim;
}

double ScriptedSoccerPolicy::shot_speed(double distance_m) {
  return std::min(kMaxShot_mps, std::sqrt(kArriveSpeed_mps * kArriveSpeed_mps +
                                          2 * kRollingDecel_mps2 * distance_m));
}

void ScriptedSoccerPolicy::chase(std::span<const float> o, const View& v, std::span<float> a) {
  const Eigen::Vector2d ball = v.ball.head<2>();
  // An opponent nearer the ball has it (unless it is down): walking into it falls (on match
  // seeds 1-12, 275 of 313 falls in 2v2 came with another player within 0.8 m in the second
  // before). Keep off it, goal-side of the ball, until the ball is nearer me.
  const Eigen::Vector2d* holder = nullptr;
  for (std::size_t k = 0; k < v.opponents.size(); ++k) {
    const Eigen::Vector2d& p = v.opponents[k];
    if (!v.opponent_down[k] && (p - ball).norm() < ball.norm() &&
        (!holder || (p - ball).norm() < (*holder - ball).norm()))
      holder = &p;
  }
  if (holder) {
    doing_ = "yield";
    lined_up_ = false;
    // Beside its way to my goal, on my side of it: in its way, its pushes knock the ball into me.
    const Eigen::Vector2d back = (v.own_goal - ball).normalized();
    const double side = left_of(back).dot(-ball) >= 0 ? 1 : -1;
    Eigen::Vector2d spot = ball + (back * 0.5 + left_of(back) * side * 0.87) * kKeepOffBall_m;
    if ((spot - *holder).norm() < kKeepOffHolder_m)
      spot = *holder + (spot - *holder).normalized() * kKeepOffHolder_m;
    return walk(o, spot, bearing(ball), a);
  }
  // At the goal's middle: in a match the keeper-aware aim of the penalty kick turned the
  // dribble away from any defender near the goal (not measured yet, so not changed).
  const Eigen::Vector2d aim = v.goal;

  // Where I stand against the line from the ball to the aim: `along` < 0 behind the ball.
  const Eigen::Vector2d dir = (aim - ball).normalized();
  const Eigen::Vector2d me = -ball;  // my root, relative to the ball
  const double along = me.dot(dir);
  const double off_line = std::abs(dir.x() * me.y() - dir.y() * me.x());
  if (lined_up_)
    lined_up_ = along < 0.1 && off_line < kLoseLine_m;
  else
    lined_up_ = along < -0.2 && along > -kBehind_m - 0.4 && off_line < kLinedUp_m;
  if ((v.goal - ball).norm() < kShootFrom_m || pressed_within_shot(v)) return kick_chase(o, v, a);
  if (lined_up_) return doing_ = "push", walk(o, ball + dir * kThrough_m, bearing(dir), a);

  doing_ = "approach";
  Eigen::Vector2d target = ball - dir * kBehind_m;
  if (along > -0.3 && off_line < 0.9) {
    doing_ = "round";
    // On the wrong side of the ball, or too close beside it: round it, on my side of the line.
    const Eigen::Vector2d perp(-dir.y(), dir.x());
    const double side = perp.dot(me) >= 0 ? 1 : -1;
    target = ball - dir * (kBehind_m + 0.3) + perp * side * 1.0;
  }
  walk(o, target, bearing(target.norm() > 1.0 ? target : dir), a);
}

void ScriptedSoccerPolicy::keep_goal(std::span<const float> o, const View& v, std::span<float> a) {
  const Eigen::Vector2d ball = v.ball.head<2>(), vel = v.ball_velocity.head<2>();
  const Eigen::Vector2d out = (v.goal - v.own_goal).normalized(), across = left_of(out);
  // Across the line: where a shot coming at the goal will cross it, else toward the ball's side.
  // It faces the ball, arms out at its sides (the zero pose): a wide body across the shot.
  const double ball_out = (ball - v.own_goal).dot(out), closing = -vel.dot(out);
  double y = (ball - v.own_goal).dot(across) * kFollowBall;
  if (closing > kShotComing_mps && ball_out > 0)
    y = (ball - v.own_goal).dot(across) + vel.dot(across) * ball_out / closing;
  y = std::clamp(y, -kPostInside_m, kPostInside_m);
  const Eigen::Vector2d spot = v.own_goal + out * kKeeperOut_m + across * y;
  walk(o, spot, bearing(ball), a);
}

std::unique_ptr<Policy> make_scripted_soccer() { return std::make_unique<ScriptedSoccerPolicy>(); }

}  // namespace olympics::client
