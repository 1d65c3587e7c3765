#include "racket/racket_match.h"

#include <algorithm>
#include <cmath>

#include "core/humanoid_assets.h"
#include "core/rotation.h"
#include "core/self_observation.h"
#include "core/state_hash.h"
#include "equipment/landing.h"
#include "racket/ball_launcher.h"
#include "racket/racket_equipment.h"
#include "racket/racket_rewards.h"

namespace olympics::sports::racket {
namespace {

constexpr int kSelfObs = kSmplSelfObservation;
constexpr int kTaskObs = 26;
constexpr int kPerOther = 3;

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

int entity_of(const core::Humanoid& h) {
  dGeomID g = dBodyGetFirstGeom(h.ode_body(0));
  return static_cast<core::GeomTag*>(dGeomGetData(g))->entity;
}

void put(std::span<float> out, size_t& k, const Eigen::Vector3d& v) {
  for (int i = 0; i < 3; ++i) out[k++] = static_cast<float>(v[i]);
}

}  // namespace

std::vector<int> racket_mode_teams(RacketMode mode) {
  switch (mode) {
    case RacketMode::BallReturn:
      return {0};
    case RacketMode::Singles:
      return {0, 1};
    case RacketMode::Doubles:
      return {0, 0, 1, 1};
  }
  return {};
}

std::vector<LayoutBlock> racket_task_layout(int slots) {
  std::vector<LayoutBlock> blocks = {
      {"ball_position", 3, "m", "ball centre relative to the root, heading frame"},
      {"ball_velocity", 3, "m/s", "ball velocity, heading frame"},
      {"racket_position", 3, "m", "racket/paddle face centre relative to the root, heading frame"},
      {"racket_normal", 3, "unit", "face normal (the hand's z axis), heading frame"},
      {"target", 3, "m", "where this player's next stroke should land, relative to the root"},
      {"landing", 3, "m", "the ball's predicted landing (eq. 6), relative to the root"},
      {"court_position", 2, "m",
       "root x, y in court coordinates seen from this side (own "
       "baseline at negative x, net at x = 0)"},
      {"court_heading", 2, "cos, sin", "heading relative to facing the net"},
      {"rally", 4, "flags / count",
       "struck (C), ball coming to my team, bounces on the "
       "receiver's side since the last stroke, touched the net"},
  };
  if (slots > 1)
    blocks.push_back({"others", kPerOther * (slots - 1), "m",
                      "per other slot in slot order: root position relative to the root, heading "
                      "frame"});
  return blocks;
}

std::vector<std::string> racket_reward_names() { return {"racket", "contact", "landing", "hits"}; }

RacketMatch::RacketMatch(const RacketMatchConfig& config, const MatchSettings& settings)
    : config_(config),
      teams_(racket_mode_teams(config.mode)),
      time_limit_ticks_(static_cast<int>(settings.time_limit_s * 30.0 + 0.5)),
      rng_(settings.seed),
      flight_(config.game.ball, config.game.ball.restitution, config.game.ball.friction),
      probe_(config.game.ball.radius),
      arena_(config.game.arena()),
      referee_(config.game, teams_, config.mode == RacketMode::Doubles,
               config.game.on_table && config.mode == RacketMode::Doubles),
      term_names_(racket_reward_names()) {
  const core::ModelSpec& spec = equipped_humanoid(config_.game.equipment);
  hand_body_ = spec.body_index(config_.game.equipment.hand);
  const int n = slot_count();
  for (int i = 0; i < n; ++i) {
    scene_.add_humanoid(spec, start_placement(i));
    entity_of_slot_.push_back(entity_of(scene_.humanoid(i)));
    falls_.emplace_back(spec, std::vector<std::string>{config_.game.equipment.hand});
    const equipment::EquipmentSpec& e = config_.game.equipment;
    discs_.push_back({i, e.face, {}, {}, e.restitution, e.friction});
  }
  const int first_server = std::uniform_int_distribution<int>(0, 1)(rng_);
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
  outcome_.reward.assign(n, 0.0f);
  outcome_.terms.assign(n, std::vector<float>(term_names_.size(), 0.0f));
  outcome_.done.assign(n, 0);
  outcome_.truncated.assign(n, 0);
  outcome_.scores.assign(team_count(), 0.0f);
  start_point();
}

core::RootPlacement RacketMatch::start_placement(int slot) const {
  const int side = RacketGame::side_sign(teams_[slot]);
  double y = 0;
  if (config_.mode == RacketMode::Doubles)
    y = (member_index(teams_, slot) == 0 ? 1 : -1) * side * config_.game.partner_y;
  // Facing the net: team 0 (at -x) looks along +x, team 1 along -x.
  return {{side * config_.game.player_x, y, 0}, side < 0 ? 0.0 : M_PI};
}

equipment::Pose RacketMatch::racket_pose(int slot) const {
  return equipment::equipment_face_pose(scene_.humanoid(slot), hand_body_, config_.game.equipment);
}

Eigen::Vector2d RacketMatch::draw_target(int slot) {
  const RacketGame& g = config_.game;
  const int opponent_side = -RacketGame::side_sign(teams_[slot]);
  const double x = std::uniform_real_distribution<double>(g.target_x_lo, g.target_x_hi)(rng_);
  const double y = std::uniform_real_distribution<double>(-g.target_y, g.target_y)(rng_);
  return {opponent_side * x, y};
}

void RacketMatch::start_point() {
  const bool doubles = config_.mode == RacketMode::Doubles;
  int receiving_team = 0, fed_slot = 0;
  if (scoreboard_) {
    for (int i = 0; i < slot_count(); ++i) {
      scene_.humanoid(i).reset(start_placement(i));
      falls_[i].reset();
    }
    receiving_team = scoreboard_->server();
    // In doubles the partners take the feed in turn.
    const int member = doubles ? served_points_ % 2 : 0;
    for (int i = 0; i < slot_count(); ++i)
      if (teams_[i] == receiving_team && member_index(teams_, i) == member) fed_slot = i;
    ++served_points_;
  }
  referee_.start_point(receiving_team, fed_slot, time_);
  referee_events_seen_ = 0;
  for (int i = 0; i < slot_count(); ++i) {
    struck_[i] = 0;
    target_[i] = draw_target(i);
    reaction_[i].setZero();
  }
  Launch launch;
  if (config_.mode == RacketMode::BallReturn) {
    launch = ball_return_launch(config_.game, 0, rng_);
  } else {
    const int y_sign = start_placement(fed_slot).position.y() >= 0 ? 1 : -1;
    launch = feed_launch(config_.game, receiving_team, y_sign, doubles, rng_);
  }
  flight_.set_state(launch.position, launch.velocity);
}

void RacketMatch::physics_step(std::vector<equipment::BallContact>& contacts) {
  const double h = scene_.settings().physics_dt();
  const int n = slot_count();
  for (int i = 0; i < n; ++i) {
    discs_[i].from = racket_pose(i);
    if (!reaction_[i].isZero()) {  // the ball's push on the racket, spread over this step
      const Eigen::Vector3d f = reaction_[i] / h;
      const Eigen::Vector3d& at = reaction_at_[i];
      dBodyAddForceAtPos(scene_.humanoid(i).ode_body(hand_body_), f.x(), f.y(), f.z(), at.x(),
                         at.y(), at.z());
      reaction_[i].setZero();
    }
  }
  scene_.physics_step();
  for (int i = 0; i < n; ++i) discs_[i].to = racket_pose(i);
  const Eigen::Vector3d from = flight_.position();
  contacts.clear();
  flight_.step(h, arena_, discs_, contacts);
  const double t0 = time_;
  time_ += h;
  for (const auto& c : contacts) handle_contact(c, t0 + c.time);
  probe_bodies(from, time_);
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
  referee_.racket_hit(slot, t);
  if (referee_.events().size() == before) return;  // the same stroke, still on the strings
  if (referee_.call() || referee_.last_hitter() != slot) return;
  struck_[slot] = 1;
  for (int i = 0; i < slot_count(); ++i)
    if (teams_[i] != teams_[slot]) struck_[i] = 0, target_[i] = draw_target(i);
}

void RacketMatch::probe_bodies(const Eigen::Vector3d& from, double t) {
  if (referee_.call()) return;
  auto touch = probe_.first_touch(scene_.world(), from, flight_.position(),
                                  [this](int, int body) { return body == hand_body_; });
  if (!touch) return;
  const auto it = std::find(entity_of_slot_.begin(), entity_of_slot_.end(), touch->entity);
  if (it == entity_of_slot_.end()) return;
  referee_.body_touch(static_cast<int>(it - entity_of_slot_.begin()), t);
  flight_.set_state(touch->centre, equipment::bounce(flight_.velocity(), Eigen::Vector3d::Zero(),
                                                     touch->normal, 0.3, 0.5));
}

void RacketMatch::step(const std::vector<std::span<const float>>& actions) {
  if (outcome_.match_over) return;
  for (int i = 0; i < slot_count(); ++i) scene_.set_action(i, actions[i]);
  std::vector<equipment::BallContact> contacts;
  for (int s = 0; s < scene_.settings().substeps; ++s) physics_step(contacts);
  ++tick_;
  tick_events_ = nlohmann::json::array();

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
    const auto terms = racket_reward_terms(in);
    outcome_.terms[i].assign(terms.begin(), terms.end());
    outcome_.reward[i] = terms[0] + terms[1] + terms[2] + terms[3];
  }
  settle_point();
}

void RacketMatch::settle_point() {
  // A fall loses the point; when both sides fall on the same tick the point is played again.
  int fallen_slot[2] = {-1, -1};
  for (int i = 0; i < slot_count(); ++i) {
    if (!falls_[i].fallen(scene_.humanoid(i))) continue;
    tick_events_.push_back({{"call", "fall"}, {"slot", i}, {"body", falls_[i].culprit()}});
    fallen_slot[teams_[i]] = i;
  }
  if (scoreboard_ && fallen_slot[0] >= 0 && fallen_slot[1] >= 0 && !referee_.call()) {
    tick_events_.push_back({{"call", "let"}, {"reason", "both sides fell"}});
    start_point();
  } else {
    for (int team = 0; team < 2; ++team)
      if (fallen_slot[team] >= 0) referee_.concede(team, fallen_slot[team], "fall");
  }
  referee_.check_stall(time_, config_.max_rally_s);
  const auto& events = referee_.events();
  for (; referee_events_seen_ < events.size(); ++referee_events_seen_)
    tick_events_.push_back(events[referee_events_seen_]);

  const bool ball_return = config_.mode == RacketMode::BallReturn;
  if (ball_return && !referee_.call() && referee_.striker_team() == 0 && referee_.bounces() == 1) {
    ++hits_[0];  // the return landed in: count it, and here comes the next ball
    tick_events_.push_back({{"call", "return_in"}, {"slot", 0}, {"returns", hits_[0]}});
    outcome_.scores[0] = static_cast<float>(hits_[0]);
    start_point();
  }
  if (const auto& call = referee_.call()) {
    nlohmann::json point = {{"n", points_.size() + 1},
                            {"winner_team", call->winner_team},
                            {"reason", call->reason},
                            {"culprit_slot", call->culprit_slot},
                            {"tick", tick_}};
    if (ball_return) {
      points_.push_back(point);
      outcome_.info = {{"events", tick_events_}, {"points", points_}, {"returns_in", hits_[0]}};
      return outcome_.end("point_lost: " + call->reason, -1);
    }
    scoreboard_->point_won(call->winner_team);
    point["score"] = scoreboard_->text();
    points_.push_back(point);
    const auto s = scoreboard_->scores();
    outcome_.scores = {s[0], s[1]};
    if (scoreboard_->over()) {
      outcome_.info = {
          {"events", tick_events_}, {"score", scoreboard_->to_json()}, {"points", points_}};
      return outcome_.end("match_won", scoreboard_->winner());
    }
    start_point();
  }
  outcome_.info = {{"events", tick_events_}};
  if (scoreboard_) outcome_.info["score"] = scoreboard_->to_json();
  if (tick_ >= time_limit_ticks_) {
    outcome_.info["points"] = points_;
    for (auto& t : outcome_.truncated) t = 1;
    outcome_.end("time_limit", scoreboard_ ? scoreboard_->leader() : -1);
  }
}

void RacketMatch::forfeit(int losing_team, const std::string& reason) {
  if (outcome_.match_over) return;
  outcome_.end(reason, forfeit_winner(team_count(), losing_team));
}

int RacketMatch::obs_size() const { return kSelfObs + kTaskObs + kPerOther * (slot_count() - 1); }

void RacketMatch::observe(int slot, std::span<float> out) const {
  const core::Humanoid& me = scene_.humanoid(slot);
  const auto bodies = me.body_states();
  core::write_self_observation(bodies, out.subspan(0, kSelfObs));
  const core::BodyState& root = bodies[0];
  const Eigen::Quaterniond to_heading = core::inverse_heading(root.orientation);
  auto rel = [&](const Eigen::Vector3d& p) -> Eigen::Vector3d {
    return to_heading * (p - root.position);
  };
  const RacketGame& g = config_.game;
  const equipment::Pose racket = racket_pose(slot);
  const Eigen::Vector2d land =
      equipment::predict_landing(flight_.position(), flight_.velocity(), g.surface_height);
  size_t k = kSelfObs;
  put(out, k, rel(flight_.position()));
  put(out, k, to_heading * flight_.velocity());
  put(out, k, rel(racket.position));
  put(out, k, to_heading * (racket.orientation * Eigen::Vector3d::UnitZ()));
  put(out, k, rel({target_[slot].x(), target_[slot].y(), g.surface_height}));
  put(out, k, rel({land.x(), land.y(), g.surface_height}));
  const double side = -RacketGame::side_sign(teams_[slot]);  // +1 for team 0
  out[k++] = static_cast<float>(root.position.x() * side);
  out[k++] = static_cast<float>(root.position.y() * side);
  const Eigen::Vector3d forward = root.orientation * Eigen::Vector3d::UnitX();
  const double yaw = std::atan2(forward.y(), forward.x()) - (side > 0 ? 0.0 : M_PI);
  out[k++] = static_cast<float>(std::cos(yaw));
  out[k++] = static_cast<float>(std::sin(yaw));
  out[k++] = struck_[slot] ? 1.0f : 0.0f;
  out[k++] = referee_.receiver_team() == teams_[slot] ? 1.0f : 0.0f;
  out[k++] = static_cast<float>(referee_.bounces());
  out[k++] = referee_.netted() ? 1.0f : 0.0f;
  for (int other = 0; other < slot_count(); ++other)
    if (other != slot) put(out, k, rel(scene_.humanoid(other).body_state(0).position));
}

std::uint64_t RacketMatch::state_hash() const {
  const Eigen::Vector3d& p = flight_.position();
  const Eigen::Vector3d& v = flight_.velocity();
  const double ball[6] = {p.x(), p.y(), p.z(), v.x(), v.y(), v.z()};
  return core::state_hash(scene_, ball);
}

}  // namespace olympics::sports::racket
