#include "racket/racket_match.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/humanoid_assets.h"
#include "equipment/landing.h"
#include "racket/ball_launcher.h"
#include "racket/racket_equipment.h"
#include "racket/racket_rewards.h"
#include "racket/racket_scene.h"

namespace olympics::sports::racket {
namespace {

constexpr int kPerOther = 3;
// The field of the k-th other player in the block "others": its root position.
std::string other_field(int k) { return "position_" + std::to_string(k); }

// The SMPL humanoid holding this equipment; built once per kind of equipment.
const core::ModelSpec& equipped_humanoid(const equipment::EquipmentSpec& equipment) {
  static const core::ModelSpec racket = [] {
    core::ModelSpec s = core::load_humanoid(core::HumanoidKind::Smpl);
    equipment::attach_equipment(s, tennis_racket());
    return s;
  }();
  static const core::ModelSpec paddle = [] {
    core::ModelSpec s = core::load_humanoid(core::HumanoidKind::Smpl);
    equipment::attach_equipment(s, table_tennis_paddle());
    return s;
  }();
  return equipment.name == "racket" ? racket : paddle;
}

// Index of a slot among its team's slots (0 or 1).
int member_index(const std::vector<int>& teams, int slot) {
  int k = 0;
  for (int s = 0; s < slot; ++s) k += teams[s] == teams[slot];
  return k;
}

}  // namespace

std::vector<LayoutBlock> racket_task_layout(int slots) {
  std::vector<LayoutBlock> blocks = {
      LayoutBlock::of("ball_position", "m", "ball centre relative to the root, heading frame",
                      {{"position", 3}}),
      LayoutBlock::of("ball_velocity", "m/s", "ball velocity, heading frame", {{"velocity", 3}}),
      LayoutBlock::of("racket_position", "m",
                      "racket/paddle face centre relative to the root, heading frame",
                      {{"position", 3}}),
      LayoutBlock::of("racket_normal", "unit", "face normal (the hand's z axis), heading frame",
                      {{"normal", 3}}),
      LayoutBlock::of("target", "m",
                      "where this player's next stroke should land, relative to the root",
                      {{"position", 3}}),
      LayoutBlock::of("landing", "m", "the ball's predicted landing (eq. 6), relative to the root",
                      {{"position", 3}}),
      LayoutBlock::of("court_position", "m",
                      "root x, y in court coordinates seen from this side (own baseline at "
                      "negative x, net at x = 0)",
                      {{"x", 1}, {"y", 1}}),
      LayoutBlock::of("court_heading", "cos, sin", "heading relative to facing the net",
                      {{"cos", 1}, {"sin", 1}}),
      LayoutBlock::of("rally", "flags / count",
                      "struck (C), ball coming to my team, bounces on the receiver's side since "
                      "the last stroke, touched the net",
                      {{"struck", 1}, {"coming", 1}, {"bounces", 1}, {"netted", 1}}),
  };
  if (slots > 1) {
    std::vector<FieldSize> others;
    for (int k = 0; k + 1 < slots; ++k) others.push_back({other_field(k), kPerOther});
    blocks.push_back(LayoutBlock::of(
        "others", "m",
        "per other slot in slot order: root position relative to the root, heading frame", others));
  }
  return blocks;
}

std::vector<RewardTerm> racket_rewards() {
  return {{"racket", 1.0, "exp(-|p_racket - p_ball|^2) until this player strikes the ball (C = 0)"},
          {"contact", 1.0, "1 once it has struck the ball (C = 1)"},
          {"landing", 1.0, "exp(-|p_land - p_target|^2), predicted landing (eq. 6), once C = 1"},
          {"hits", 1.0, "table tennis: successful returns this episode, once C = 1"}};
}

std::vector<RefereeCall> racket_calls() {
  return {
      {"hit", "a racket struck the ball"},
      {"bounce", "the ball bounced on the playing surface (x, y)"},
      {"floor", "the ball hit the floor off the table (table tennis; x, y)"},
      {"net", "the ball touched the net"},
      {"dead_ball", "the ball stopped: it counts as bouncing again where it lies"},
      {"body_touch", "the ball touched a player's body"},
      {"point", "a point is decided: winner_team, reason, culprit_slot, strokes (by both sides)",
       kAnnounced},
      {"fall", "a player fell (body): that side loses the point"},
      {"let",
       "the point is played again: both sides fell at once, or (reason net_serve) a serve touched "
       "the net and landed in",
       kAnnounced},
      {"toss", "start: serve: the ball is tossed for the server (slot)"},
      {"serve_in",
       "start: serve: the serve landed in (slot: the server); the receiver must play it"},
      {"fault",
       "start: serve: the serve was not good (reason: not_struck, out, net, not_over, "
       "no_bounce_on_own_court); tennis serves again once, then loses the point "
       "(double_fault); table tennis loses it (fault)"},
      {"return_in", "ball return: the return landed in; the next ball comes"}};
}

RacketMatch::RacketMatch(const RacketMatchConfig& config, const ModeSpec& mode, Layout layout,
                         const MatchSettings& settings)
    : SmplMatch(mode, std::move(layout), settings),
      config_(config),
      flight_(config.game.ball, config.game.ball.restitution, config.game.ball.friction),
      probe_(config.game.ball.radius),
      arena_(config.game.arena()),
      referee_(config.game, mode.slot_teams, config.mode == RacketMode::Doubles,
               config.game.on_table && config.mode == RacketMode::Doubles) {
  const core::ModelSpec& spec = equipped_humanoid(config_.game.equipment);
  hand_body_ = spec.body_index(config_.game.equipment.hand);
  const int n = slot_count();
  for (int i = 0; i < n; ++i) {
    add_player(spec, start_placement(i), {config_.game.equipment.hand});
    const equipment::EquipmentSpec& e = config_.game.equipment;
    discs_.push_back({i, e.face, {}, {}, e.restitution, e.friction});
  }
  const int first_server = std::uniform_int_distribution<int>(0, 1)(rng());
  if (config_.mode != RacketMode::BallReturn) {
    if (config_.game.on_table)
      scoreboard_ = std::make_unique<TableTennisScore>(config_.table_tennis, first_server);
    else
      scoreboard_ = std::make_unique<TennisScore>(config_.tennis, first_server);
  }
  target_.assign(n, Eigen::Vector2d::Zero());
  struck_.assign(n, 0);
  hits_.assign(n, 0);
  reaction_.assign(n, Eigen::Vector3d::Zero());
  reaction_at_.assign(n, Eigen::Vector3d::Zero());
  start_point();
}

core::RootPlacement RacketMatch::start_placement(int slot) const {
  const int side = RacketGame::side_sign(teams()[slot]);
  double y = 0;
  if (config_.mode == RacketMode::Doubles)
    y = (member_index(teams(), slot) == 0 ? 1 : -1) * side * config_.game.partner_y;
  if (server_slot_ >= 0 && teams()[slot] == teams()[server_slot_]) {
    // A server stands diagonally opposite where its serve must land (its partner beside it);
    // table-tennis singles serve from anywhere behind the end line.
    const int away = -receiver_y_sign();
    if (config_.mode == RacketMode::Doubles)
      y = (slot == server_slot_ ? away : -away) * config_.game.partner_y;
    else if (!config_.game.on_table)
      y = away * config_.game.serve_y;
  }
  const bool on_own_left = -side * y > 0;  // its y as it faces the net, left +
  double x = config_.game.player_x;
  if (config_.mode == RacketMode::Doubles) x -= config_.game.partner_forward(on_own_left);
  // Facing the net: team 0 (at -x) looks along +x, team 1 along -x; a server on the ad court (its
  // left of the centre mark) turned to its right (clockwise seen from above) by the game's
  // ad_serve_turn.
  const double turn = slot == server_slot_ && on_own_left ? config_.game.ad_serve_turn : 0.0;
  return {{side * x, y, 0}, (side < 0 ? 0.0 : M_PI) - turn};
}

equipment::Pose RacketMatch::racket_pose(int slot) const {
  return equipment::equipment_face_pose(player(slot), hand_body_, config_.game.equipment);
}

Eigen::Vector2d RacketMatch::draw_target(int slot) {
  const RacketGame& g = config_.game;
  const int opponent_side = -RacketGame::side_sign(teams()[slot]);
  const double x = std::uniform_real_distribution<double>(g.target_x_lo, g.target_x_hi)(rng());
  const double y = std::uniform_real_distribution<double>(-g.target_y, g.target_y)(rng());
  return {opponent_side * x, y};
}

void RacketMatch::reset_players() {
  for (int i = 0; i < slot_count(); ++i) reset_player(i, start_placement(i));
}

void RacketMatch::start_point() {
  const bool doubles = config_.mode == RacketMode::Doubles;
  int receiving_team = 0, fed_slot = 0;
  if (scoreboard_) {
    reset_players();
    receiving_team = scoreboard_->server();
    const int member = doubles ? doubles_member(receiving_team) : 0;
    for (int i = 0; i < slot_count(); ++i)
      if (teams()[i] == receiving_team && member_index(teams(), i) == member) fed_slot = i;
    ++served_points_;
    if (config_.serve) {
      server_slot_ = fed_slot;
      faults_ = 0;
      return toss();
    }
  }
  feed(receiving_team, fed_slot);
}

void RacketMatch::feed(int receiving_team, int fed_slot) {
  fed_slot_ = fed_slot;
  referee_.start_point(receiving_team, fed_slot, time());
  referee_events_seen_ = 0;
  for (int i = 0; i < slot_count(); ++i) {
    struck_[i] = 0;
    target_[i] = draw_target(i);
    reaction_[i].setZero();
  }
  Launch launch;
  if (config_.mode == RacketMode::BallReturn) {
    launch = ball_return_launch(config_.game, 0, rng());
  } else {
    const double receiver_y = start_placement(fed_slot).position.y();
    launch = config_.feed_to_player
                 ? feed_to_player_launch(config_.game, receiving_team, receiver_y, rng())
                 : feed_launch(config_.game, receiving_team, receiver_y >= 0 ? 1 : -1,
                               config_.mode == RacketMode::Doubles, rng());
  }
  flight_.set_state(launch.position, launch.velocity);
}

int RacketMatch::doubles_member(int team) {
  // The feed: the partners take it in turn, point by point.
  if (!config_.serve) return served_points_ % 2;
  // The serve: one partner keeps it for the team's whole turn (tennis: a game, a tie-break's
  // first point then two at a time; table tennis: two points, one from 10-10) and the partners
  // take the turns in order, so the four serve A1, B1, A2, B2 (ITF rule 14; ITTF 2.14.1-2.14.2).
  if (team != serving_team_) {
    serving_team_ = team;
    ++service_turns_[team];
  }
  return (service_turns_[team] - 1) % 2;
}

int RacketMatch::receiver_y_sign() const {
  // Tennis serves from the right (deuce) court when the game's points so far are even, the
  // left otherwise (ITF rule 8; a tie-break too); table-tennis doubles from the right half to the
  // right half (ITTF 2.6.3); the receiver's right is the server's diagonal.
  const int server_team = teams()[server_slot_];
  const int right_to_right = -RacketGame::side_sign(server_team);
  if (config_.game.on_table) return config_.mode == RacketMode::Doubles ? right_to_right : 0;
  const auto* tennis = dynamic_cast<const TennisScore*>(scoreboard_.get());
  const int played = tennis ? tennis->points()[0] + tennis->points()[1] : 0;
  return played % 2 == 0 ? right_to_right : -right_to_right;
}

void RacketMatch::toss() {
  reset_players();
  const RacketGame& g = config_.game;
  ServeRule rule;
  rule.server_slot = server_slot_;
  rule.receiver_y_sign = receiver_y_sign();
  rule.second_serve = faults_ > 0;
  rule.limit_s = g.serve_limit_s;
  referee_.start_serve(teams()[server_slot_], rule, time());
  referee_events_seen_ = 0;
  for (int i = 0; i < slot_count(); ++i) {
    struck_[i] = 0;
    target_[i] = draw_target(i);
    reaction_[i].setZero();
  }
  // In front of the server's racket (right) side, rising straight up.
  const core::RootPlacement at = start_placement(server_slot_);
  const Eigen::Vector2d forward(std::cos(at.yaw), std::sin(at.yaw));
  const Eigen::Vector2d right(forward.y(), -forward.x());
  // A hand's toss is never quite the same: the seed moves it by up to toss_jitter m each way
  // and its speed by up to toss_speed_jitter m/s.
  std::uniform_real_distribution<double> jitter(-1, 1);
  const double forward_by = g.toss_forward + g.toss_jitter * jitter(rng());
  const double side_by = g.toss_side + g.toss_jitter * jitter(rng());
  const double speed = g.toss_speed + g.toss_speed_jitter * jitter(rng());
  const Eigen::Vector2d xy = at.position.head<2>() + forward_by * forward + side_by * right;
  flight_.set_state({xy.x(), xy.y(), g.toss_z}, {0, 0, speed});
}

void RacketMatch::before_physics_step() {
  const double h = scene().settings().physics_dt();
  for (int i = 0; i < slot_count(); ++i) {
    discs_[i].from = racket_pose(i);
    if (!reaction_[i].isZero()) {  // the ball's push on the racket, spread over this step
      const Eigen::Vector3d f = reaction_[i] / h;
      const Eigen::Vector3d& at = reaction_at_[i];
      dBodyAddForceAtPos(player(i).ode_body(hand_body_), f.x(), f.y(), f.z(), at.x(), at.y(),
                         at.z());
      reaction_[i].setZero();
    }
  }
}

void RacketMatch::after_physics_step(double step_start) {
  for (int i = 0; i < slot_count(); ++i) discs_[i].to = racket_pose(i);
  const Eigen::Vector3d from = flight_.position();
  contacts_.clear();
  flight_.step(scene().settings().physics_dt(), arena_, discs_, contacts_);
  for (const auto& c : contacts_) handle_contact(c, step_start + c.time);
  probe_bodies(from, time());
}

void RacketMatch::handle_contact(const equipment::BallContact& c, double t) {
  switch (c.kind) {
    case equipment::SurfaceKind::Ground:
      return referee_.surface_contact(kGround, c.centre, t);
    case equipment::SurfaceKind::Box:
      return referee_.surface_contact(static_cast<ArenaSurface>(c.id), c.centre, t);
    case equipment::SurfaceKind::Disc:
      break;
  }
  const int slot = c.id;
  const Eigen::Vector3d impulse = config_.game.ball.mass * (c.v_after - c.v_before);
  reaction_[slot] -= impulse;
  reaction_at_[slot] = c.centre - c.normal * config_.game.ball.radius;
  const size_t before = referee_.events().size();
  referee_.racket_hit(slot, t, c.centre);
  if (referee_.events().size() == before) return;  // the same stroke, still on the strings
  if (referee_.call() || referee_.last_hitter() != slot) return;
  struck_[slot] = 1;
  for (int i = 0; i < slot_count(); ++i)
    if (teams()[i] != teams()[slot]) struck_[i] = 0, target_[i] = draw_target(i);
}

void RacketMatch::probe_bodies(const Eigen::Vector3d& from, double t) {
  if (referee_.call()) return;
  auto touch = probe_.first_touch(scene().world(), from, flight_.position(),
                                  [this](int, int body) { return body == hand_body_; });
  const int slot = touch ? slot_of_entity(touch->entity) : -1;
  if (slot < 0) return;
  referee_.body_touch(slot, t);
  flight_.set_state(touch->centre, equipment::bounce(flight_.velocity(), Eigen::Vector3d::Zero(),
                                                     touch->normal, 0.3, 0.5));
}

void RacketMatch::log_referee_calls() {
  const auto& calls = referee_.events();
  for (; referee_events_seen_ < calls.size(); ++referee_events_seen_)
    log(calls[referee_events_seen_]);
}

void RacketMatch::settle_tick() {
  // Rewards for this tick, before a finished point resets anything.
  const RacketGame& g = config_.game;
  for (int i = 0; i < slot_count(); ++i) {
    RewardInput in;
    in.racket = racket_pose(i).position;
    in.ball = flight_.position();
    in.ball_velocity = flight_.velocity();
    in.target = target_[i];
    in.struck = struck_[i];
    in.hits = hits_[i];
    in.counts_hits = g.reward_counts_hits;
    in.landing_height = g.surface_height;
    set_reward(i, racket_reward_terms(in));
  }

  // A fall loses the point, even on the tick of a serve's fault or let (the ball was in play when
  // the player fell); when both sides fall on the same tick the point is played again.
  int fallen_slot[2] = {-1, -1};
  for (int i = 0; i < slot_count(); ++i)
    if (down(i)) fallen_slot[teams()[i]] = i;
  const bool both_fell =
      scoreboard_ && fallen_slot[0] >= 0 && fallen_slot[1] >= 0 && !referee_.call();
  if (both_fell && !config_.serve) {
    // The point is played again: the tick's calls so far, the let, and the same player fed again
    // from where the players stand at a point's start (in doubles, not the partner whose turn
    // the next point is).
    log_referee_calls();
    nlohmann::json let = referee_event("let", time(), fed_slot_);
    let["reason"] = "both sides fell";
    log(std::move(let));
    reset_players();
    feed(teams()[fed_slot_], fed_slot_);
  } else if (both_fell) {
    referee_.let("both sides fell", time());  // the same server tosses again, below
    faults_ = 0;  // the whole point is replayed, from the first serve (ITF rule 23, case 1)
  } else {
    for (int team = 0; team < 2; ++team)
      if (fallen_slot[team] >= 0) referee_.concede(team, fallen_slot[team], "fall");
  }
  referee_.check_stall(time(), config_.max_rally_s);
  log_referee_calls();
  if (referee_.replay() != RallyReferee::Replay::None) {  // a first fault or a let: serve again
    faults_ += referee_.replay() == RallyReferee::Replay::Fault;
    toss();
  }

  const bool ball_return = config_.mode == RacketMode::BallReturn;
  if (ball_return && !referee_.call() && referee_.striker_team() == 0 && referee_.bounces() == 1) {
    ++hits_[0];  // the return landed in: count it, and here comes the next ball
    nlohmann::json in = referee_event("return_in", time(), 0);
    in["returns"] = hits_[0];
    log(std::move(in));
    outcome_.scores[0] = static_cast<float>(hits_[0]);
    start_point();
  }
  if (const auto& call = referee_.call()) {
    nlohmann::json point = {{"n", points_.size() + 1},       {"winner_team", call->winner_team},
                            {"reason", call->reason},        {"culprit_slot", call->culprit_slot},
                            {"strokes", referee_.strokes()}, {"tick", tick()}};
    if (ball_return) {
      points_.push_back(point);
      outcome_.info = {{"points", points_}, {"returns_in", hits_[0]}};
      return outcome_.end("point_lost: " + call->reason, -1);
    }
    scoreboard_->point_won(call->winner_team);
    point["score"] = scoreboard_->text();
    points_.push_back(point);
    const auto s = scoreboard_->scores();
    outcome_.scores = {s[0], s[1]};
    if (scoreboard_->over()) {
      outcome_.info = {{"score", scoreboard_->to_json()}, {"points", points_}};
      return outcome_.end("match_won", scoreboard_->winner());
    }
    start_point();
  }
  if (scoreboard_) outcome_.info["score"] = scoreboard_->to_json();
}

void RacketMatch::on_time_limit() {
  outcome_.info["points"] = points_;
  end_by_time_limit(scoreboard_ ? scoreboard_->leader() : -1);
}

void RacketMatch::write_task_observation(int slot, const HeadingFrame& frame,
                                         ObservationWriter& out) const {
  const RacketGame& g = config_.game;
  const equipment::Pose racket = racket_pose(slot);
  const Eigen::Vector2d land =
      equipment::predict_landing(flight_.position(), flight_.velocity(), g.surface_height);
  out.begin("ball_position").field("position").put(frame.point(flight_.position()));
  out.begin("ball_velocity").field("velocity").put(frame.vector(flight_.velocity()));
  out.begin("racket_position").field("position").put(frame.point(racket.position));
  out.begin("racket_normal")
      .field("normal")
      .put(frame.vector(racket.orientation * Eigen::Vector3d::UnitZ()));
  out.begin("target")
      .field("position")
      .put(frame.point({target_[slot].x(), target_[slot].y(), g.surface_height}));
  out.begin("landing").field("position").put(frame.point({land.x(), land.y(), g.surface_height}));
  const double side = -RacketGame::side_sign(teams()[slot]);  // +1 for team 0
  const Eigen::Vector3d& root = frame.root.position;
  out.begin("court_position").field("x").put(root.x() * side).field("y").put(root.y() * side);
  const Eigen::Vector3d forward = frame.root.orientation * Eigen::Vector3d::UnitX();
  const double yaw = std::atan2(forward.y(), forward.x()) - (side > 0 ? 0.0 : M_PI);
  out.begin("court_heading").field("cos").put(std::cos(yaw)).field("sin").put(std::sin(yaw));
  out.begin("rally")
      .field("struck")
      .put(struck_[slot] ? 1.0 : 0.0)
      .field("coming")
      .put(referee_.receiver_team() == teams()[slot] ? 1.0 : 0.0)
      .field("bounces")
      .put(referee_.bounces())
      .field("netted")
      .put(referee_.netted() ? 1.0 : 0.0);
  if (slot_count() == 1) return;
  out.begin("others");
  int k = 0;
  for (int other = 0; other < slot_count(); ++other)
    if (other != slot)
      out.field(other_field(k++)).put(frame.point(player(other).body_state(0).position));
}

void RacketMatch::extra_state(std::vector<double>& values) const {
  const Eigen::Vector3d& p = flight_.position();
  const Eigen::Vector3d& v = flight_.velocity();
  values.insert(values.end(), {p.x(), p.y(), p.z(), v.x(), v.y(), v.z()});
}

void RacketMatch::describe_scene(SceneBuilder& scene) const {
  describe_racket_arena(config_.game, scene);
  scene.add_sphere(scene.add_body("ball", -1, "ball"), Eigen::Vector3d::Zero(),
                   config_.game.ball.radius, "ball");
}

void RacketMatch::extra_scene_poses(std::vector<float>& out) const {
  append_pose(out, flight_.position(), Eigen::Quaterniond::Identity());
}

}  // namespace olympics::sports::racket
