#include "soccer/soccer_match.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/humanoid_assets.h"
#include "core/state_hash.h"
#include "framework/ball_observation.h"
#include "framework/jittered_start.h"
#include "framework/team_observation.h"

namespace olympics::sports::soccer {
namespace {

const core::ModelSpec& player_model() {
  static const core::ModelSpec spec = core::load_humanoid(core::HumanoidKind::Smpl);
  return spec;
}

constexpr double kKickerBehind_m = 2.0;  // the penalty kicker starts this far behind the ball

}  // namespace

SoccerMode soccer_mode(const std::string& mode) {
  if (mode == "penalty_kick") return SoccerMode::PenaltyKick;
  if (mode == "penalty_kick_keeper") return SoccerMode::PenaltyKickKeeper;
  return SoccerMode::TeamPlay;
}

std::vector<LayoutBlock> soccer_task_layout(const ModeSpec& mode) {
  std::vector<LayoutBlock> blocks = {
      ball_observation_block(),
      LayoutBlock::of("goals", "m",
                      "the centre of the goal I attack (3) and of the goal I defend (3), at half "
                      "the goal's height, relative to the root, heading frame",
                      {{"attack", 3}, {"defend", 3}}),
      LayoutBlock::of("field", "m, cos, sin",
                      "my root from the centre spot along my attack direction and across it (left "
                      "positive); my heading relative to the attack direction (cos, sin)",
                      {{"along", 1}, {"across", 1}, {"heading_cos", 1}, {"heading_sin", 1}})};
  append_team_blocks(mode, blocks);
  blocks.push_back(LayoutBlock::of(
      "match", "goals, fraction, flag, half",
      "my side's goals, the other side's goals, share of the match time left, the restart being "
      "waited for (+1 mine to take, -1 theirs, 0 ball in play), the half (0, 1)",
      {{"my_goals", 1}, {"their_goals", 1}, {"time_left", 1}, {"restart", 1}, {"half", 1}}));
  return blocks;
}

std::vector<RefereeCall> soccer_calls() {
  return {
      {"goal",
       "the whole ball crossed the goal line in the goal (slot: scorer, team, "
       "assist_slot, own_goal)",
       kAnnounced},
      {"out", "the whole ball left the field (line: touch or goal; last_touch_slot)", kAnnounced},
      {"restart", "play restarts (kind: throw_in, free_kick, goal_kick, corner; team, x, y)",
       kAnnounced},
      {"kick_off", "play (re)starts from the centre (team: the side that kicks off)", kAnnounced},
      {"half_time", "the teams change ends (half)", kAnnounced},
      {"encroachment",
       "an opponent played a restart before the taking side: taken again "
       "(culprit_slot)",
       kAnnounced},
      {"stood_up", "a player down for the set time was stood up where it lay"},
      {"fall", "a player fell (body)"}};
}

SoccerMatch::SoccerMatch(const SoccerConfig& config, const ModeSpec& mode, Layout layout,
                         const MatchSettings& settings)
    : SmplMatch(mode, std::move(layout), settings),
      config_(config),
      kind_(soccer_mode(mode.name)),
      guard_(equipment::soccer_ball().radius),
      referee_(config.field, config.rules, mode.slot_teams, equipment::soccer_ball().radius) {
  config_.field.build(scene().world());
  const double r = equipment::soccer_ball().radius;
  if (kind_ == SoccerMode::TeamPlay) {
    spawn_ = {0, 0, r};
  } else {
    spawn_ = {config_.field.half_length() - config_.penalty_distance, 0, r};
  }
  ball_ = std::make_unique<equipment::Ball>(scene().world(), equipment::soccer_ball(), spawn_);
  ball_->sense_contacts();
  touch_tick_.assign(slot_count(), -1);
  root_before_.resize(slot_count());
  for (int s = 0; s < slot_count(); ++s) add_player(player_model(), {});
  if (kind_ == SoccerMode::TeamPlay) {
    const int first = std::uniform_int_distribution<int>(0, 1)(rng());
    referee_.start(first, 0.0);
    kick_off_positions(first);
    nlohmann::json e = referee_event("kick_off", 0.0);
    e["team"] = first;
    log(std::move(e));
  } else {
    reset_player(0, placement(spawn_.head<2>() - Eigen::Vector2d(kKickerBehind_m, 0), 1));
    if (kind_ == SoccerMode::PenaltyKickKeeper)
      reset_player(1, placement({config_.field.half_length() - 0.3, 0}, -1));
  }
  remember_positions();
}

core::RootPlacement SoccerMatch::placement(const Eigen::Vector2d& at, int facing) {
  return jittered_start(at, facing > 0 ? 0.0 : M_PI, rng());
}

int SoccerMatch::attack(int slot) const {
  if (kind_ != SoccerMode::TeamPlay) return team_of(slot) == 0 ? 1 : -1;
  return referee_.attack_direction(team_of(slot));
}

// Kick-off: every player in its own half; the kicking side's first player just behind the
// ball, its second deeper; the other side outside the centre circle.
void SoccerMatch::kick_off_positions(int kicking_team) {
  std::array<int, 2> index{};
  const double keep = std::max(config_.rules.restart_distance, Field::kCentreCircle) + 0.5;
  for (int s = 0; s < slot_count(); ++s) {
    const int team = team_of(s), i = index[team]++;
    const int d = referee_.attack_direction(team);
    Eigen::Vector2d at;
    if (team == kicking_team)
      at = i == 0 ? Eigen::Vector2d(-d * 0.6, 0) : Eigen::Vector2d(-d * 5.0, 3.0);
    else
      at = i == 0 ? Eigen::Vector2d(-d * keep, 0) : Eigen::Vector2d(-d * (keep + 3), -3.0);
    reset_player(s, placement(at, d));
  }
  ball_->set_state({0, 0, ball_->spec().radius}, Eigen::Vector3d::Zero());
}

// Any opponent nearer the restart's spot than the restart distance goes back to it, on the
// line from the spot to its own goal, facing the ball.
void SoccerMatch::clear_restart_area(const Restart& r) {
  ball_->set_state({r.spot.x(), r.spot.y(), ball_->spec().radius}, Eigen::Vector3d::Zero());
  const double keep = config_.rules.restart_distance;
  for (int s = 0; s < slot_count(); ++s) {
    if (team_of(s) == r.team) continue;
    const Eigen::Vector2d root = player(s).body_state(0).position.head<2>();
    if ((root - r.spot).norm() >= keep) continue;
    Eigen::Vector2d away = config_.field.goal_centre(-attack(s)).head<2>() - r.spot;
    away = away.norm() > 1e-6 ? Eigen::Vector2d(away.normalized()) : Eigen::Vector2d(-attack(s), 0);
    const Eigen::Vector2d at = r.spot + (keep + 0.3) * away;
    const Eigen::Vector2d look = r.spot - at;
    reset_player(s, {{at.x(), at.y(), 0}, std::atan2(look.y(), look.x())});
  }
}

void SoccerMatch::before_physics_step() {
  const double dt = scene().settings().physics_dt();
  ball_->prepare_step(dt);
  guard_.before_step(scene().world(), *ball_, dt);
}

void SoccerMatch::after_physics_step(double) {
  const Eigen::Vector3d ball = ball_->position();
  if (!crossed_at_ && config_.field.crossed(ball, ball_->spec().radius) != Crossed::None)
    crossed_at_ = ball;
  for (const auto& c : scene().world().sensed_contacts()) {
    const int s = c.other ? slot_of_entity(c.other->entity) : -1;
    if (s < 0) continue;
    touch_tick_[s] = tick() + 1;  // the tick being stepped
    if (kind_ == SoccerMode::TeamPlay) referee_.touch(s, time());
    last_toucher_ = s;
  }
}

RewardState SoccerMatch::reward_state(int slot) const {
  RewardState s;
  s.root_before = root_before_[slot];
  s.root = player(slot).body_state(0).position;
  s.ball_before = ball_before_;
  s.ball = ball_->position();
  s.ball_velocity = ball_->velocity();
  s.attack = attack(slot);
  s.target = config_.field.goal_centre(s.attack);
  s.fallen = down(slot);
  return s;
}

void SoccerMatch::remember_positions() {
  for (int s = 0; s < slot_count(); ++s) root_before_[s] = player(s).body_state(0).position;
  ball_before_ = ball_->position();
}

void SoccerMatch::settle_tick() {
  const Eigen::Vector3d judged = crossed_at_.value_or(ball_->position());
  crossed_at_.reset();
  if (kind_ == SoccerMode::TeamPlay)
    settle_team_play(judged);
  else
    settle_penalty(judged);
  if (outcome_.match_over) outcome_.info["goals"] = goals_;
  remember_positions();
}

void SoccerMatch::settle_penalty(const Eigen::Vector3d& judged) {
  int end = 0;
  const Crossed crossed = config_.field.crossed(judged, ball_->spec().radius, &end);
  const bool goal = crossed == Crossed::Goal && end == 1;
  set_reward(0, penalty_kick_terms(reward_state(0), spawn_, goal));
  if (kind_ == SoccerMode::PenaltyKickKeeper)
    set_reward(1, goalkeeper_terms(reward_state(1), goal));
  const int keeper_wins = kind_ == SoccerMode::PenaltyKickKeeper ? 1 : -1;
  if (goal) {
    outcome_.scores[0] = 1;
    GoalCall kick;  // the kicker's (no assist in a penalty)
    kick.team = 0, kick.scorer = 0;
    record_goal(kick);
  } else if (crossed != Crossed::None) {
    record_out(crossed == Crossed::TouchLine ? "touch" : "goal", last_toucher_);
  }
  outcome_.info["score"] = score_json();
  if (goal) return outcome_.end("goal", 0);
  if (crossed != Crossed::None) return outcome_.end("missed", keeper_wins);
}

void SoccerMatch::settle_team_play(const Eigen::Vector3d& judged) {
  if (config_.stand_up) stand_up_fallen([this](int s) { return attack(s) > 0 ? 0.0 : M_PI; });
  const auto stop = referee_.update(judged, time());
  const int scoring = stop && stop->goal ? stop->goal->team : -1;
  for (int s = 0; s < slot_count(); ++s) {
    const int goal = scoring < 0 ? 0 : (team_of(s) == scoring ? 1 : -1);
    set_reward(s, team_play_terms(reward_state(s), goal));
  }
  const auto& score = referee_.score();
  outcome_.scores = {static_cast<float>(score[0]), static_cast<float>(score[1])};
  if (stop) {
    log_stoppage(*stop);
    carry_out(*stop);
  }
  outcome_.info["score"] = score_json();
}

void SoccerMatch::record_goal(const GoalCall& g) {
  nlohmann::json e = referee_event("goal", time(), g.scorer);
  e["team"] = g.team;
  e["assist_slot"] = g.assist;
  e["own_goal"] = g.own_goal;
  log(std::move(e));
  goals_.push_back({{"team", g.team},
                    {"scorer_slot", g.scorer},
                    {"assist_slot", g.assist},
                    {"own_goal", g.own_goal},
                    {"t", tenths(time())},
                    {"score", score_json()["text"]}});
}

void SoccerMatch::record_out(const std::string& line, int last_touch) {
  nlohmann::json e = referee_event("out", time());
  e["line"] = line;
  e["last_touch_slot"] = last_touch;
  log(std::move(e));
}

void SoccerMatch::log_stoppage(const Stoppage& s) {
  if (s.goal) {
    record_goal(*s.goal);
  } else if (s.reason == "out") {
    record_out(s.line, s.last_touch);
  } else if (s.reason == "half_time") {
    nlohmann::json e = referee_event("half_time", time());
    e["half"] = referee_.half();
    log(std::move(e));
  } else if (s.reason == "encroachment") {
    nlohmann::json e = referee_event("encroachment", time());
    e["culprit_slot"] = s.culprit;
    log(std::move(e));
  }
  const Restart& r = s.restart;
  nlohmann::json e = referee_event(r.kind == RestartKind::KickOff ? "kick_off" : "restart", time());
  e["team"] = r.team;
  if (r.kind != RestartKind::KickOff) {
    e["kind"] = restart_name(r.kind);
    e["x"] = tenths(r.spot.x());
    e["y"] = tenths(r.spot.y());
  }
  log(std::move(e));
}

void SoccerMatch::carry_out(const Stoppage& s) {
  if (s.restart.kind == RestartKind::KickOff)
    kick_off_positions(s.restart.team);
  else
    clear_restart_area(s.restart);
}

nlohmann::json SoccerMatch::score_json() const {
  const int a = static_cast<int>(outcome_.scores[0]);
  const int b = team_count() > 1 ? static_cast<int>(outcome_.scores[1]) : 0;
  nlohmann::json j = {{"goals", {a, b}}, {"text", std::to_string(a) + "-" + std::to_string(b)}};
  if (kind_ == SoccerMode::TeamPlay) j["half"] = referee_.half() + 1;
  return j;
}

void SoccerMatch::on_time_limit() {
  outcome_.info["goals"] = goals_;
  end_by_time_limit(leading_team());
}

void SoccerMatch::write_task_observation(int slot, const HeadingFrame& frame,
                                         ObservationWriter& out) const {
  const int d = attack(slot);
  write_ball_observation(*ball_, frame, out);
  out.begin("goals")
      .field("attack")
      .put(frame.point(config_.field.goal_centre(d)))
      .field("defend")
      .put(frame.point(config_.field.goal_centre(-d)));
  const Eigen::Vector3d& root = frame.root.position;
  const double relative = core::heading_angle(frame.root.orientation) - (d > 0 ? 0.0 : M_PI);
  out.begin("field")
      .field("along")
      .put(d * root.x())
      .field("across")
      .put(d * root.y())
      .field("heading_cos")
      .put(std::cos(relative))
      .field("heading_sin")
      .put(std::sin(relative));
  write_team_blocks(*this, slot, frame, out);
  const int mine = team_of(slot);
  const double theirs_score = team_count() > 1 ? outcome_.scores[1 - mine] : 0.0;
  double restart = 0;
  if (const auto& p = referee_.pending(); p && kind_ == SoccerMode::TeamPlay)
    restart = p->team == mine ? 1 : -1;
  out.begin("match")
      .field("my_goals")
      .put(outcome_.scores[mine])
      .field("their_goals")
      .put(theirs_score)
      .field("time_left")
      .put(1.0 - static_cast<double>(tick()) / time_limit_ticks())
      .field("restart")
      .put(restart)
      .field("half")
      .put(kind_ == SoccerMode::TeamPlay ? referee_.half() : 0);
}

void SoccerMatch::extra_state(std::vector<double>& values) const {
  core::append_body_state(ball_->body(), values);
}

void SoccerMatch::describe_scene(SceneBuilder& scene) const {
  config_.field.describe(scene);
  const int ball = scene.add_body("ball", -1, "ball");
  scene.add_sphere(ball, Eigen::Vector3d::Zero(), ball_->spec().radius, "ball", "#f8f8f8");
}

void SoccerMatch::extra_scene_poses(std::vector<float>& out) const {
  append_pose(out, ball_->position(), ball_->orientation());
}

}  // namespace olympics::sports::soccer
