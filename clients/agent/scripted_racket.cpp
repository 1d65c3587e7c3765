#include "scripted_racket.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "control/drive_target.h"
#include "control/minimum_jerk.h"
#include "control/serve_plan.h"
#include "control/smpl_limbs.h"
#include "control/stroke_plan.h"
#include "scripted_racket_play.h"
#include "scripted_tennis_swing.h"
#include "smpl_observation.h"

namespace olympics::client {
namespace {

using namespace smpl;
using control::BallSample;
using control::BodyPose;
using control::CourtFrame;

using racket_play::Play;

// The arc swing about the vertical through `pivot` that brings the face to `contact` moving at
// `speed` (m/s) along `direction`: its turning rate (rad/s, the face's speed over its radius,
// no less than 0.2 m) and its sense (+1: turning left).
struct ArcTurn {
  double rate, sense;
};
ArcTurn arc_turn(const Eigen::Vector3d& contact, const Eigen::Vector3d& pivot,
                 const Eigen::Vector3d& direction, double speed) {
  Eigen::Vector3d radius = contact - pivot;
  radius.z() = 0;
  return {speed / std::max(0.2, radius.norm()),
          Eigen::Vector3d::UnitZ().cross(radius).dot(direction) > 0 ? 1.0 : -1.0};
}

}  // namespace

struct ScriptedRacketPolicy::Sport {
  explicit Sport(const sports::racket::RacketGame& g)
      : game(g),
        play(g.on_table ? racket_play::table_play() : racket_play::tennis_play()),
        path(g),
        model(control::BodyModel::humanoid(core::HumanoidKind::Smpl, &g.equipment)),
        arm(model,
            control::LimbIk(model,
                            play.trunk_reach > 0 ? control::smpl_right_arm_and_trunk()
                                                 : control::smpl_right_arm(),
                            g.equipment.face_centre, Eigen::Vector3d::UnitZ()),
            play.gravity_scale) {}
  sports::racket::RacketGame game;
  Play play;
  control::BallPath path;
  control::BodyModel model;
  control::LimbControl arm;
  // The ball's centre is this far off the face's centre plane at contact.
  double face_back = game.ball.radius + game.equipment.face.half_thickness;
  // The arm's own reach, from the shoulder to the face centre.
  // The arm's posture at contact (a LimbIk solution) for the joint-space swing; empty: none yet.
  std::vector<Eigen::Matrix3d> contact_arm;
  double arm_reach = control::LimbIk(model, control::smpl_right_arm(), game.equipment.face_centre,
                                     Eigen::Vector3d::UnitZ())
                         .reach();
};

ScriptedRacketPolicy::ScriptedRacketPolicy() = default;
ScriptedRacketPolicy::~ScriptedRacketPolicy() = default;

void ScriptedRacketPolicy::start(const MatchInfo& match) {
  if (match.sport != "tennis" && match.sport != "table_tennis")
    throw std::invalid_argument("the scripted racket policy plays tennis and table tennis, not " +
                                match.sport);
  const ObservationLayout& l = match.observation;
  blocks_ = {l.offset("ball_position", "position"), l.offset("ball_velocity", "velocity"),
             l.offset("court_position", "x"),       l.offset("court_position", "y"),
             l.offset("court_heading", "cos"),      l.offset("court_heading", "sin"),
             l.offset("rally", "struck"),           l.offset("rally", "coming"),
             l.offset("rally", "bounces"),          l.offset("landing", "position")};
  const bool table = match.sport == "table_tennis";
  if (!sport_ || sport_->game.on_table != table)
    sport_ = std::make_unique<Sport>(table ? sports::racket::table_tennis_game()
                                           : sports::racket::tennis_game(1.0));
  control_dt_ = match.control_dt;
  others_.clear();
  for (int k = 0; l.has("others", "position_" + std::to_string(k)); ++k)
    others_.push_back(l.offset("others", "position_" + std::to_string(k)));
  doubles_ = match.mode == "2v2";
  struck_this_turn_ = was_coming_ = false;
  my_turn_ = -1;
  legs_.reset();
  stroke_.reset();
  sport_->contact_arm.clear();
  since_stroke_s_ = 1e9;
  missed_ = false;
  sport_->arm.reset();
}

double ScriptedRacketPolicy::rally_reach() const {
  return sport_->play.reach_fraction * sport_->arm_reach + sport_->play.trunk_reach;
}

void ScriptedRacketPolicy::plan(std::span<const float> o, const CourtFrame& court,
                                const BodyPose& pose) {
  const Play& play = sport_->play;
  const auto& game = sport_->game;
  const Eigen::Vector3d ball = court.point(vec3(o, blocks_.ball));
  const Eigen::Vector3d velocity = court.vector(vec3(o, blocks_.ball_velocity));
  const int bounced = static_cast<int>(std::lround(o[blocks_.bounces]));
  const std::vector<BallSample> path =
      sport_->path.predict(ball, velocity, play.horizon_s, bounced);
  const Eigen::Vector3d shoulder = pose.position[kRShoulder];
  const double reach = rally_reach();
  const double face_back = sport_->face_back;
  const Eigen::Vector3d meet = play.meet_spot.value_or(play.sweet_spot);  // heading frame
  const Eigen::Vector3d spot = court.vector(meet);  // where balls are met from the root, court

  // Where to meet the ball: after its one bounce on the own side, clear of the table. Points
  // within reach now cost their distance from where balls are met; others the walk to where they
  // would be (that point at the ball), more than the legs can cover in the time left
  // weighing most.
  auto stance_of = [&](const BallSample& s) {
    Eigen::Vector3d stance = s.position - spot;
    stance.z() = 0;
    return stance;
  };
  const BallSample* best = nullptr;
  double best_cost = 1e9;
  bool best_reachable = false;
  for (const BallSample& s : path) {
    if (s.own_bounces != 1 || s.other_bounces > 0 || s.time < play.commit_s) continue;
    if (game.on_table && s.position.x() > -game.half_length - 0.03 &&
        s.position.z() < game.surface_height + play.table_clearance)
      continue;
    const Eigen::Vector3d face =
        court.to_heading_point(s.position - Eigen::Vector3d(face_back, 0, 0));
    const double height = face.z() - meet.z();
    if (height < -play.below || height > play.above) continue;
    // An arc swing meets the ball beside the shoulder, where the arc runs toward the net.
    const Eigen::Vector2d beside = (face - shoulder).head<2>();
    const bool arc_forward =
        play.max_back_angle <= 0 || std::abs(beside.y()) >= 0.6 * beside.norm();
    const bool reachable = face.x() > 0.2 && arc_forward && (face - shoulder).norm() <= reach;
    double cost;
    if (reachable) {
      cost = 0.5 * (face - meet).norm();
    } else {
      const double walk = (s.position - spot - court.root).head<2>().norm();
      cost = 0.5 + 0.3 * walk + 3 * std::max(0.0, walk - play.walk_speed * (s.time - 0.2));
    }
    if (stroke_) cost += 0.5 * std::abs(s.time - (stroke_->time_to_hit - control_dt_));
    if (cost < best_cost) best_cost = cost, best = &s, best_reachable = reachable;
  }
  // Where the stroke should land (doubles may aim elsewhere than singles and ball return).
  const Eigen::Vector2d aim = doubles_ && play.doubles_aim ? *play.doubles_aim : play.aim;
  if (best && play.max_back_angle > 0 && !play.arc_speeds.empty()) {
    // The arc: about the vertical through the shoulder where the body will be at contact; a
    // forehand (turning left) right of the shoulder, a backhand left of it.
    const Eigen::Vector3d root = best_reachable ? court.root : Eigen::Vector3d(stance_of(*best));
    const Eigen::Vector3d pivot = root + court.vector(shoulder);
    const auto tangent =
        control::arc_tangent(best->position - Eigen::Vector3d(face_back, 0, 0), pivot);
    if (tangent) {
      // The least listed speed that returns the ball in, by bisection (a faster face sends the
      // ball further: a search over the normals at every speed costs too much of the tick).
      auto shot_at = [&](double speed) {
        return control::plan_shot_at_speed(sport_->path, best->position, best->velocity,
                                           speed * *tangent, aim, play.net_margin, 0.5);
      };
      std::optional<control::ShotPlan> shot;
      int lo = -1, hi = static_cast<int>(play.arc_speeds.size()) - 1;
      if (auto fastest = shot_at(play.arc_speeds[hi])) {
        shot = fastest;
        while (hi - lo > 1) {
          const int mid = (lo + hi) / 2;
          if (auto s = shot_at(play.arc_speeds[mid]))
            shot = s, hi = mid;
          else
            lo = mid;
        }
      }
      if (shot) {
        stroke_ = Stroke{best->time,       best->position, shot->face.normal, shot->face.direction,
                         shot->face.speed, best_reachable, stance_of(*best),  pivot};
        return;
      }
    }
  }
  if (best) {
    // The swing's line: level, toward where the ball should go (measured: more balls met than
    // swung along the face's normal, which draws the face down under a rising ball).
    const Eigen::Vector2d toward = (aim - best->position.head<2>()).normalized();
    const Eigen::Vector3d swing(toward.x(), toward.y(), 0);
    const auto shot = control::plan_shot(sport_->path, best->position, best->velocity, aim,
                                         play.net_margin, swing);
    if (shot) {
      stroke_ = Stroke{best->time,       best->position, shot->face.normal, shot->face.direction,
                       shot->face.speed, best_reachable, stance_of(*best),  std::nullopt};
      return;
    }
  }
  if (stroke_) {  // keep the stroke planned: the ball is on its way there
    stroke_->time_to_hit -= control_dt_;
    if (stroke_->time_to_hit < -play.commit_s) stroke_.reset();
  }
}

void ScriptedRacketPolicy::drive_arm(const CourtFrame& court, const BodyPose& pose,
                                     bool legs_walking, std::span<float> a) {
  const Play& play = sport_->play;
  const double face_back = sport_->face_back;

  const Eigen::Vector3d root_velocity(root_velocity_.x(), root_velocity_.y(), 0);
  // Drawn back by the swing's length, then swung through the ball at the planned speed; no
  // further back than the arm reaches (a goal out of reach bends the whole swing).
  double speed = 0, back = 0;
  if (stroke_) {
    // The cap is the straight swing's; an arc's speed is chosen from what the arm delivers.
    speed = stroke_->pivot ? stroke_->speed : std::clamp(stroke_->speed, 0.0, play.max_speed);
    const Eigen::Vector3d contact = court.to_heading_point(stroke_->ball_at) -
                                    court.to_heading_vector(stroke_->normal) * face_back;
    const Eigen::Vector3d line = court.to_heading_vector(stroke_->direction);
    const Eigen::Vector3d shoulder = pose.position[kRShoulder];
    back = std::min(play.max_back, speed * play.swing_s);
    // The reach the planner met the ball within, the trunk's lean included (within the arm's
    // alone, a ball met with the trunk's help had hardly any backswing and fell short: issue 29,
    // seventh round, tuning seeds 1-300: not over 50 -> 25 balls, returns in 37.5% -> 41.5%;
    // unseen seeds 121001 on: 36.3% -> 39.0%, docs/racket-sports.md).
    while (back > 0.02 && (contact - line * back - shoulder).norm() > rally_reach()) back -= 0.02;
  }
  // Within reach and, where the sport waits for it, the legs no longer walking: swung from here.
  // The server stands where it tossed: the legs keep it on that spot (a few cm of drift, so they
  // "walk" every tick), which must not hold its swing back (it did: 1v1 first serves in 18 -> 3
  // of 200 on tuning seeds 41-240, the arm readied by inverse kinematics until 0.5 s before
  // contact; docs/racket-sports.md, the serve's second round).
  const bool swing_ready = stroke_ && stroke_->reachable &&
                           !(play.swing_once_settled && legs_walking && !stroke_->serve);
  auto ready = [&] {
    control::LimbGoal g;
    g.position = play.sweet_spot + Eigen::Vector3d(-0.1, 0, 0);
    g.axis = court.to_heading_vector(Eigen::Vector3d::UnitX());
    return g;
  };
  // The face's pose at time `ahead` from now: along the stroke's line, or ready.
  auto goal_at = [&](double ahead) {
    control::LimbGoal g;
    if (stroke_) {
      const Eigen::Vector3d contact = stroke_->ball_at - stroke_->normal * face_back;
      Eigen::Vector3d face, normal = stroke_->normal;
      if (stroke_->pivot) {
        // Along the arc: the face and its normal turned about the pivot's vertical.
        const auto [rate, turning] =
            arc_turn(contact, *stroke_->pivot, stroke_->direction, play.arc_drive * speed);
        const double angle =
            std::clamp(rate * (ahead - stroke_->time_to_hit),
                       -std::min(swing_ready ? play.max_back_angle : play.walking_back_angle,
                                 rate * play.swing_s),
                       play.follow_angle);
        const Eigen::Matrix3d turn =
            Eigen::AngleAxisd(turning * angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
        face = *stroke_->pivot + turn * (contact - *stroke_->pivot);
        normal = turn * normal;
      } else {
        const double along = std::clamp(speed * (ahead - stroke_->time_to_hit), -back, play.follow);
        face = contact + stroke_->direction * along;
      }
      // Where it is then relative to where the root will be then (the body may still be moving);
      // a ball out of reach yet is prepared for as seen from where the legs are taking the body.
      CourtFrame seen_from = court;
      if (!swing_ready) seen_from.root.head<2>() = stroke_->stance.head<2>();
      const Eigen::Vector3d met = seen_from.to_heading_point(contact);
      g.position = seen_from.to_heading_point(face) - root_velocity * ahead +
                   racket_play::face_aim_bias(play, met, pose.position[kRShoulder]);
      g.axis = court.to_heading_vector(normal);
      // Doubles keeps either face (not measured there; its partners-apart test came nearer its
      // bar: close ticks 2.8% -> 5.3% against 5%).
      g.axis_either_sign = !play.front_face_only || doubles_;
      if (!stroke_->pivot && play.draw_s > 0) {
        // Drawn back only in time for the swing: until then the face waits at the ready point
        // (an arm held back across the body while the legs step topples the player).
        const double until_swing = stroke_->time_to_hit - ahead - (speed > 0 ? back / speed : 0);
        const double drawn = control::minimum_jerk(1 - until_swing / play.draw_s);
        const control::LimbGoal r = ready();
        g.position = r.position + drawn * (g.position - r.position);
        const Eigen::Vector3d axis = r.axis + drawn * (g.axis - r.axis);
        if (axis.norm() > 1e-6) g.axis = axis.normalized();
      }
    } else {
      g = ready();
    }
    return g;
  };
  bool counter_arm = false;
  if (play.joint_swing && stroke_ && stroke_->pivot && swing_ready) {
    // The posture that meets the ball where the body stands now, solved from the last tick's
    // (it changes little from tick to tick), turned back about the shoulder by the arc's angle.
    const Eigen::Vector3d contact = stroke_->ball_at - stroke_->normal * face_back;
    control::LimbGoal meet;
    meet.position = court.to_heading_point(contact);
    meet.axis = court.to_heading_vector(stroke_->normal);
    auto& posture = sport_->contact_arm;
    posture = sport_->arm.ik().solve(pose, meet, posture, posture.empty() ? 40 : 10).relative;
    const auto [rate, turning] =
        arc_turn(contact, *stroke_->pivot, stroke_->direction, play.arc_drive * speed);
    SwingTurn turn = swing_turn(play.ask_ahead_s + play.swing_lead_s - stroke_->time_to_hit, rate,
                                play.max_back_angle, play.follow_angle);
    turn.angle *= turning, turn.rate *= turning, turn.acceleration *= turning;
    // The serve is swung at 10 m/s and more: its inertial load held, the free arm against it.
    drive_turned_arm(sport_->model, sport_->arm.ik(), pose, posture, turn, play.gravity_scale, a,
                     stroke_->serve);
    if (stroke_->serve) {
      drive_counter_arm(sport_->model, pose, turn, play.gravity_scale, a);
      counter_arm = true;
    }
    sport_->arm.reset();  // the IK arc starts afresh when it takes over again
  } else {
    sport_->contact_arm.clear();
    const control::LimbGoal now = goal_at(play.ask_ahead_s);
    sport_->arm.drive(pose, now, goal_at(play.ask_ahead_s + control_dt_), control_dt_, a);
  }
  // The trunk held straight against the swinging arm's weight; the free arm hangs at the side.
  static constexpr int kTorso[] = {control::kSmplTorso};
  static constexpr int kTrunk[] = {control::kSmplTorso, control::kSmplSpine, control::kSmplChest,
                                   control::kSmplRThorax};
  control::hold_against_gravity(
      sport_->model, pose,
      play.trunk_reach > 0 ? std::span<const int>(kTorso) : std::span<const int>(kTrunk), a,
      play.gravity_scale);
  if (!counter_arm) set_joint(a, kLShoulder, 0, -1.2);
}

bool ScriptedRacketPolicy::plan_serve(std::span<const float> o, const CourtFrame& court,
                                      const BodyPose& pose) {
  const Play& play = sport_->play;
  const Eigen::Vector3d ball = court.point(vec3(o, blocks_.ball));
  const Eigen::Vector3d velocity = court.vector(vec3(o, blocks_.ball_velocity));
  if (o[blocks_.bounces] > 0.5 || !control::is_toss(ball, velocity, court.root)) return false;
  // Standing still, the arm meets the falling toss; planned once (the toss flies as predicted),
  // unless the stroke is a rally's left from the point before (elsewhere than the toss).
  if (stroke_ && (stroke_->ball_at - ball).head<2>().norm() < 0.2) {
    stroke_->time_to_hit -= control_dt_;
    return true;
  }
  stroke_.reset();
  const std::vector<BallSample> toss = sport_->path.predict(ball, velocity, 2.0);
  const Eigen::Vector3d shoulder = court.point(pose.position[kRShoulder]);
  const double reach = play.serve_reach_fraction.value_or(play.reach_fraction) * sport_->arm_reach;
  const control::ServeAim aim = control::serve_aim(sport_->game, court.root);
  std::optional<Eigen::Vector3d> pivot;
  std::optional<control::ServePlan> serve;
  if (!play.serve_speeds.empty()) {
    pivot = shoulder;
    serve = control::plan_arc_serve(sport_->path, toss, shoulder, reach, sport_->face_back,
                                    court.point(play.sweet_spot), aim, play.net_margin,
                                    control::kServeSoonestS, play.serve_speeds);
  } else {
    serve = control::plan_serve(sport_->path, toss, shoulder, reach, sport_->face_back,
                                court.point(play.sweet_spot), aim, play.net_margin,
                                control::kServeSoonestS);
  }
  if (!serve) return true;
  // Doubles: the face and its line turned further across, for the arm's error (Play).
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(doubles_ ? play.doubles_serve_turn : 0.0, Eigen::Vector3d::UnitZ())
          .toRotationMatrix();
  Eigen::Vector3d normal = serve->shot.face.normal;
  if (pivot) {  // the arc serve: the face tilted down and turned right for the arm's error (Play)
    const Eigen::Vector3d across = Eigen::Vector3d::UnitZ().cross(normal).normalized();
    normal = Eigen::AngleAxisd(-play.serve_turn_right, Eigen::Vector3d::UnitZ()) *
             Eigen::AngleAxisd(play.serve_tilt_down, across) * normal;
  }
  stroke_ = Stroke{serve->contact.time,
                   serve->contact.position,
                   turn * normal,
                   turn * serve->shot.face.direction,
                   serve->shot.face.speed,
                   true,
                   court.root,
                   pivot,
                   true};
  return true;
}

bool ScriptedRacketPolicy::my_ball(const CourtFrame& court, const Eigen::Vector3d& partner,
                                   const Eigen::Vector3d& ball, const Eigen::Vector3d& landing,
                                   bool team_coming, bool new_point) {
  // A new point: nobody's turn yet.
  if (new_point) my_turn_ = -1, struck_this_turn_ = false;
  const bool nearer = (ball - court.root).head<2>().norm() <= (ball - partner).head<2>().norm();
  if (!sport_->game.on_table) return nearer;  // tennis: either partner; the nearer one plays
  // Table tennis: the side's first stroke of a point is taken by the partner on whose side of
  // the two the ball will land (the fed partner must take the feed, and the feed lands on its
  // line), decided once: by "nearer", both partners may go for a feed between them, or neither.
  if (my_turn_ < 0 && team_coming) {
    const double apart = court.root.y() - partner.y();
    const double off_middle = landing.y() - 0.5 * (court.root.y() + partner.y());
    if (std::abs(apart) > 0.05 && std::abs(off_middle) > 0.02)
      my_turn_ = off_middle * apart > 0 ? 1 : 0;
  }
  return my_turn_ < 0 ? nearer : my_turn_ == 1;
}

void ScriptedRacketPolicy::act(std::span<const float> o, std::span<float> a) {
  if (control_dt_ <= 0 || !sport_)
    throw std::logic_error("ScriptedRacketPolicy: act() before start()");
  if (a.size() != kActions)
    throw std::invalid_argument("the scripted racket policy drives the SMPL humanoid (69 actions)");
  std::fill(a.begin(), a.end(), 0.0f);
  const Blocks& at = blocks_;
  const Play& play = sport_->play;
  if (!legs_) legs_.emplace(play.legs, control_dt_);

  CourtFrame court;
  court.root = {o[at.court_x], o[at.court_y], smpl::root_height(o)};
  court.yaw = std::atan2(o[at.heading_sin], o[at.heading_cos]);
  const BodyPose pose = sport_->model.pose_from_observation(o);
  root_velocity_ = smpl::root_velocity(o);

  // Doubles: the partner is the other player on this side of the net.
  Eigen::Vector3d partner = court.root;
  if (doubles_)
    for (int other : others_) {
      const Eigen::Vector3d p = court.point(vec3(o, other));
      if (p.x() < 0) partner = p;
    }
  const Eigen::Vector3d ball = court.point(vec3(o, at.ball));
  // A new point: the ball put back at the feed, further than it flies in a tick. At the table
  // a ball left lying in or by the net at a point's end is put back less than 1 m away (the feed
  // starts over the net), and the new point went unseen: the stroke committed then ran on into
  // the feed and let it go (1v1 seed 1, the fifth point, with the front face); a table-tennis
  // ball flies under 0.35 m a tick.
  const bool new_point = (ball - last_ball_).norm() > (sport_->game.on_table ? 0.4 : 1.0);
  last_ball_ = ball;
  const bool team_coming = o[at.coming] > 0.5;
  bool coming = team_coming && o[at.struck] < 0.5;  // to me, not struck yet
  if (doubles_) {
    // Table tennis: partners strike in turn. When the ball leaves the team, whoever did not
    // strike this time strikes next time.
    if (o[at.struck] > 0.5) struck_this_turn_ = true;
    if (was_coming_ && !team_coming)
      my_turn_ = struck_this_turn_ ? 0 : 1, struck_this_turn_ = false;
    was_coming_ = team_coming;
    // Every tick: it watches for a new point.
    const bool mine =
        my_ball(court, partner, ball, court.point(vec3(o, at.landing)), team_coming, new_point);
    coming = coming && mine;
  }
  if (!coming || new_point) missed_ = false;
  if (new_point && play.forget_stroke_at_new_point) stroke_.reset();
  // A match puts the players back at their marks for each point; ball return does not (its
  // player walks on from where the last ball left it), so there the legs carry on.
  const bool put_back = !others_.empty();
  const bool tossed = control::hardly_moving_across(court.vector(vec3(o, at.ball_velocity)));
  if (new_point && put_back && play.fresh_legs.applies_to(doubles_, tossed)) {
    legs_.emplace(play.legs, control_dt_);
    if (play.fresh_legs.step_at_once) legs_->step_at_once_trailing_foot_first();
  }
  if (coming && stroke_ && stroke_->reachable &&
      stroke_->time_to_hit - control_dt_ < play.commit_s) {
    // Committed: the swing is under way; the ball is met where it was planned.
    stroke_->time_to_hit -= control_dt_;
    if (stroke_->time_to_hit < -play.commit_s) stroke_.reset(), missed_ = play.let_go_missed;
  } else if (coming && plan_serve(o, court, pose)) {
    // A toss to serve: the serve is planned (control/serve_plan.h).
  } else if (coming && !missed_) {
    plan(o, court, pose);
  } else if (stroke_) {
    stroke_.reset();
    since_stroke_s_ = 0;
  }
  since_stroke_s_ += control_dt_;

  // Legs: stand while the stroke is within reach; else walk to where the ball will be, or home.
  Eigen::Vector3d walk(0, 0, 0);  // court frame, from the root
  if (stroke_ && (!stroke_->reachable || stroke_->time_to_hit > play.settle_s)) {
    walk = stroke_->stance - court.root;
    walk.z() = 0;
    // A ball the legs cannot get to in time: stand rather than run after it.
    if (!stroke_->reachable && play.chase_slack > 0 &&
        walk.norm() > play.walk_speed * std::max(0.0, stroke_->time_to_hit) + play.chase_slack)
      walk.setZero();
  } else if (!coming && since_stroke_s_ > play.home_after_s) {
    // Home: the middle of the own half's back, or in doubles the own side of it.
    const double home_y =
        doubles_ ? (court.root.y() >= partner.y() ? 1 : -1) * sport_->game.partner_y : 0;
    // In doubles the partner whose ball it is not steps back out of the striker's way (tennis;
    // table tennis stands still); the partners' marks are staggered, the left one nearer the net.
    double back = doubles_ && team_coming ? play.doubles_step_back : 0;
    if (doubles_) back -= sport_->game.partner_forward(home_y > 0);
    // Table-tennis doubles (only table_play() sets it): the right-hand partner (home_y < 0 only
    // in doubles) whose stroke is next waits nearer the centre line, where the opponents' balls
    // come (Play::doubles_next_right_y).
    double wait_y = home_y;
    if (play.doubles_next_right_y && home_y < 0 && my_turn_ == 1 && !team_coming)
      wait_y = *play.doubles_next_right_y;
    walk = Eigen::Vector3d(play.home_x - back, wait_y, 0) - court.root;
  }
  walk.z() = 0;
  legs_->balance_centre_of_mass(sport_->model.centre_of_mass(pose), play.balance_ahead);
  legs_->act(o, court.to_heading_vector(walk).head<2>(), -court.yaw, a);
  if (!legs_->stepping()) control::hold_standing_legs(sport_->model, pose, a, play.gravity_scale);
  drive_arm(court, pose, walk.norm() > 1e-9, a);
}

}  // namespace olympics::client
