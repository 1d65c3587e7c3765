#include "basketball/basketball_match.h"

#include <cmath>

#include "core/humanoid_assets.h"
#include "core/state_hash.h"
#include "framework/ball_observation.h"
#include "framework/jittered_start.h"
#include "framework/team_observation.h"

namespace olympics::sports::basketball {
namespace {

const core::ModelSpec& player_model() {
  static const core::ModelSpec spec = core::load_humanoid(kHumanoid);
  return spec;
}

constexpr double kFloorTouch = 0.01;     // m: the ball's bottom this close to the floor
constexpr double kTeammateAside = 3.0;   // m: the taker's teammate beside it at a restart
constexpr double kDefendersApart = 1.2;  // m between two defenders at a restart
constexpr double kReleased_s = 0.1;      // the ball untouched by the shooter this long: released

}  // namespace

bool is_team_play(const std::string& mode) { return mode != "free_throw"; }

std::vector<LayoutBlock> basketball_task_layout(const ModeSpec& mode) {
  const LayoutBlock rim = LayoutBlock::of(
      "rim", "m", "the rim's centre relative to the root, heading frame", {{"centre", 3}});
  if (!is_team_play(mode.name))
    return {ball_observation_block(), rim,
            LayoutBlock::of("target", "m",
                            "the target of the desired launch velocity (above the rim) relative "
                            "to the ball, heading frame",
                            {{"offset", 3}}),
            LayoutBlock::of("throw", "fraction, flag",
                            "share of the time left; 1 while the ball is still being presented, "
                            "else 0",
                            {{"time_left", 1}, {"presenting", 1}})};
  std::vector<LayoutBlock> blocks = {
      ball_observation_block(), rim,
      LayoutBlock::of(
          "arc", "m",
          "how far my root and the ball are beyond the 2-point arc (negative: inside it)",
          {{"me", 1}, {"ball", 1}})};
  append_team_blocks(mode, blocks);
  blocks.push_back(LayoutBlock::of(
      "game", "points, fraction, s, flag",
      "my side's points, the other side's, share of the game time left, shot clock left (s), "
      "possession (+1 my side, -1 the other, 0 nobody yet), the side with the ball has cleared "
      "it (1, else 0), the ball is being presented to me at a restart (1, else 0)",
      {{"my_points", 1},
       {"their_points", 1},
       {"time_left", 1},
       {"shot_clock", 1},
       {"possession", 1},
       {"cleared", 1},
       {"presented_to_me", 1}}));
  return blocks;
}

std::vector<RefereeCall> basketball_calls() {
  return {
      {"basket",
       "the ball went down through the rim (slot: the shooter; points, team, counted, x and y "
       "of the release)",
       kAnnounced},
      {"not_cleared",
       "a basket by a side that had not cleared the ball behind the arc: no points "
       "(slot: the shooter)",
       kAnnounced},
      {"out", "the ball touched the floor outside the lines (last_touch_slot)", kAnnounced},
      {"from_below",
       "the ball went up through the rim from below: a violation, no basket; the other side's "
       "ball (last_touch_slot)",
       kAnnounced},
      {"shot_clock", "the side with the ball did not get a shot to the basket in time (team)",
       kAnnounced},
      {"restart", "play restarts (kind: check_ball or after_basket; team, x, y)", kAnnounced},
      {"miss",
       "free throw: the ball came down on the floor, left the court or went up through the rim "
       "without a basket (where: floor, off_court, from_below)",
       kAnnounced},
      {"fall", "a player fell (body)"},
      {"stood_up", "team play with falls: stand_up: a player down 2 s was stood up where it lay"}};
}

BasketballMatch::BasketballMatch(const BasketballConfig& config, const ModeSpec& mode,
                                 Layout layout, const MatchSettings& settings)
    : SmplMatch(mode, std::move(layout), settings),
      config_(config),
      team_play_(is_team_play(mode.name)),
      referee_(config.court, config.rules, mode.slot_teams),
      watch_(config.court) {
  config_.court.build(scene().world());
  for (int s = 0; s < slot_count(); ++s) add_player(player_model(), {});
  ball_ = std::make_unique<equipment::Ball>(scene().world(), equipment::basketball(),
                                            Eigen::Vector3d(0, 0, 1));
  root_before_.resize(slot_count());
  ball_->sense_contacts();
  if (team_play_) {
    const int first = std::uniform_int_distribution<int>(0, 1)(rng());
    const Restart r = referee_.start(first, 0.0);
    log_stoppage({"start", std::nullopt, -1, r});
    carry_out(r);
  } else {
    const Eigen::Vector2d spot(config_.court.free_throw_line_x() - kBehindLine, 0);
    const core::RootPlacement start = jittered_start(spot, 0.0, rng());
    reset_player(0, start);
    present_to(0, start);
  }
  ball_before_step_ = ball_before_tick_ = ball_->position();
  for (int s = 0; s < slot_count(); ++s) root_before_[s] = player(s).body_state(0).position;
}

Eigen::Vector3d BasketballMatch::target(int basket) const {
  return config_.court.rim_centre(basket) + Eigen::Vector3d(0, 0, kTargetAboveRim);
}

core::RootPlacement BasketballMatch::placement(const Eigen::Vector2d& at,
                                               const Eigen::Vector2d& facing) {
  return jittered_start(at, std::atan2(facing.y(), facing.x()), rng());
}

void BasketballMatch::present_to(int slot, const core::RootPlacement& at) {
  presented_slot_ = slot;
  const Eigen::Vector2d forward(std::cos(at.yaw), std::sin(at.yaw));
  const Eigen::Vector2d spot = at.position.head<2>() + kPresentForward * forward;
  present_ = {spot.x(), spot.y(), kPresentHeight};
  present_until_ = time() + config_.present_s;
  ball_->set_state(present_, Eigen::Vector3d::Zero());
  watch_.reset();
}

// The taker (the taking side's player nearest the spot) on the spot, facing as the referee says
// (the basket at a check ball, the arc it must clear under the basket); its teammate beside it,
// facing the basket they attack; the defenders `restart_distance` in front of it, facing it.
void BasketballMatch::carry_out(const Restart& r) {
  int taker = -1;
  double nearest = 1e9;
  for (int s = 0; s < slot_count(); ++s) {
    if (team_of(s) != r.team) continue;
    const double d = (player(s).body_state(0).position.head<2>() - r.spot).norm();
    if (d < nearest) nearest = d, taker = s;
  }
  const Eigen::Vector2d to_rim =
      (config_.court.rim_centre(referee_.attacks(r.team)).head<2>() - r.spot).normalized();
  const Eigen::Vector2d facing = r.facing;
  const Eigen::Vector2d across(-facing.y(), facing.x());
  const core::RootPlacement taken = placement(r.spot, facing);
  reset_player(taker, taken);
  int defender = 0;
  for (int s = 0; s < slot_count(); ++s) {
    if (s == taker) continue;
    if (team_of(s) == r.team) {
      reset_player(s, placement(r.spot + kTeammateAside * across, to_rim));
      continue;
    }
    const double side = defender++ == 0 ? 0.0 : kDefendersApart;
    const Eigen::Vector2d at = r.spot + config_.restart_distance * facing + side * across;
    reset_player(s, placement(at, r.spot - at));
  }
  present_to(taker, taken);
}

void BasketballMatch::before_physics_step() {
  ball_->prepare_step(scene().settings().physics_dt());
  ball_before_step_ = ball_->position();
}

void BasketballMatch::after_physics_step(double step_start) {
  if (step_start < present_until_) {  // still presented: it stays on its spot
    ball_->set_state(present_, Eigen::Vector3d::Zero());
    return;
  }
  const Eigen::Vector3d now = ball_->position();
  const RimPassage passage = watch_.step(ball_before_step_, now);
  if (passage.basket >= 0) basket_this_tick_ = passage.basket;
  if (passage.from_below >= 0 && from_below_this_tick_ < 0)
    from_below_this_tick_ = passage.from_below;
  if (!team_play_) {
    if (now.z() - ball_->spec().radius < kFloorTouch) touched_floor_ = true;
    for (const auto& c : scene().world().sensed_contacts())
      if (c.other && c.other->entity >= 0) shooter_touch_s_ = step_start, watch_.reset();
    return;
  }
  for (const auto& c : scene().world().sensed_contacts()) {
    if (!c.other) {  // the floor
      if (!config_.court.inside(now.head<2>())) out_this_tick_ = true;
    } else if (c.other->entity < 0) {  // the rim, its bracket, the board or the pole
      referee_.basket_touch();
    } else if (const int s = slot_of_entity(c.other->entity); s >= 0) {
      referee_.touch(s, player(s).body_state(0).position.head<2>(), time());
      watch_.reset();
    }
  }
}

void BasketballMatch::settle_tick() {
  if (team_play_) {
    settle_team_play();
    if (config_.stand_up && !outcome_.match_over)
      stand_up_fallen([this](int s) {
        const Eigen::Vector3d to_rim =
            config_.court.rim_centre(attacked_by(s)) - player(s).body_state(0).position;
        return std::atan2(to_rim.y(), to_rim.x());
      });
  } else {
    settle_free_throw();
  }
  ball_before_tick_ = ball_->position();
  for (int s = 0; s < slot_count(); ++s) root_before_[s] = player(s).body_state(0).position;
}

void BasketballMatch::settle_free_throw() {
  const bool basket = basket_this_tick_ >= 0, from_below = from_below_this_tick_ >= 0;
  basket_this_tick_ = from_below_this_tick_ = -1;
  set_reward(0, free_throw_terms(ball_->position(), ball_->velocity(), target(), basket));
  if (from_below) {  // a violation: the throw is over, no basket
    nlohmann::json e = referee_event("miss", time());
    e["where"] = "from_below";
    log(std::move(e));
    return outcome_.end("missed", -1);
  }
  if (basket) {
    outcome_.scores[0] = 1;
    nlohmann::json e = referee_event("basket", time(), 0);
    e["points"] = 1;
    log(std::move(e));
    return outcome_.end("basket", 0);
  }
  const bool off_court = !config_.court.inside(ball_->position().head<2>());
  if (touched_floor_ || off_court) {
    nlohmann::json e = referee_event("miss", time());
    e["where"] = touched_floor_ ? "floor" : "off_court";
    log(std::move(e));
    return outcome_.end("missed", -1);
  }
  // A fall ends the throw while the shooter still has the ball, not once it is in flight.
  const bool released = !presenting() && time() - shooter_touch_s_ > kReleased_s;
  if (!fell_this_tick().empty() && !released) return outcome_.end("fall", -1);
}

TeamPlayState BasketballMatch::reward_state(int slot) const {
  TeamPlayState s;
  s.root_before = root_before_[slot];
  s.root = player(slot).body_state(0).position;
  s.ball_before = ball_before_tick_;
  s.ball = ball_->position();
  s.ball_velocity = ball_->velocity();
  const int mine = team_of(slot), with_ball = referee_.possession();
  s.target = target(referee_.attacks(with_ball < 0 ? mine : with_ball));
  s.possession = with_ball < 0 ? 0 : (with_ball == mine ? 1 : -1);
  s.fallen = down(slot);
  return s;
}

void BasketballMatch::settle_team_play() {
  const std::array<int, 2> before = referee_.score();
  std::vector<TeamPlayState> states;  // possession as it was during the tick
  for (int s = 0; s < slot_count(); ++s) states.push_back(reward_state(s));
  const std::optional<Stoppage> stop =
      from_below_this_tick_ >= 0
          ? std::optional<Stoppage>(referee_.from_below(time()))
          : referee_.update(basket_this_tick_ >= 0, out_this_tick_, time(), basket_this_tick_);
  basket_this_tick_ = from_below_this_tick_ = -1;
  out_this_tick_ = false;
  const std::array<int, 2>& score = referee_.score();
  const std::array<int, 2> scored = {score[0] - before[0], score[1] - before[1]};
  for (int s = 0; s < slot_count(); ++s) {
    states[s].points = scored[team_of(s)] - scored[1 - team_of(s)];
    set_reward(s, team_play_terms(states[s]));
  }
  outcome_.scores = {static_cast<float>(score[0]), static_cast<float>(score[1])};
  if (stop) log_stoppage(*stop);
  outcome_.info["score"] = score_json();
  if (referee_.winner() >= 0) {
    write_game_summary();
    return outcome_.end("points_reached", referee_.winner());
  }
  if (stop) carry_out(stop->restart);
}

void BasketballMatch::write_game_summary() {
  outcome_.info["baskets"] = baskets_;
  outcome_.info["stoppages"] = stoppages_;
}

void BasketballMatch::log_stoppage(const Stoppage& s) {
  if (s.reason != "start") stoppages_[s.reason] = stoppages_.value(s.reason, 0) + 1;
  if (s.basket) {
    const BasketCall& b = *s.basket;
    nlohmann::json e = referee_event(b.counted ? "basket" : "not_cleared", time(), b.shooter);
    e["team"] = b.team;
    e["points"] = b.points;
    e["counted"] = b.counted;
    e["x"] = tenths(b.release.x());
    e["y"] = tenths(b.release.y());
    log(std::move(e));
    if (b.counted)
      baskets_.push_back({{"team", b.team},
                          {"shooter_slot", b.shooter},
                          {"points", b.points},
                          {"t", tenths(time())},
                          {"score", score_json()["text"]}});
  } else if (s.reason == "out") {
    nlohmann::json e = referee_event("out", time());
    e["last_touch_slot"] = s.last_touch;
    log(std::move(e));
  } else if (s.reason == "from_below") {
    nlohmann::json e = referee_event("from_below", time());
    e["last_touch_slot"] = s.last_touch;
    log(std::move(e));
  } else if (s.reason == "shot_clock") {
    nlohmann::json e = referee_event("shot_clock", time());
    e["team"] = 1 - s.restart.team;
    log(std::move(e));
  }
  nlohmann::json e = referee_event("restart", time());
  e["kind"] = restart_name(s.restart.kind);
  e["team"] = s.restart.team;
  e["x"] = tenths(s.restart.spot.x());
  e["y"] = tenths(s.restart.spot.y());
  log(std::move(e));
}

nlohmann::json BasketballMatch::score_json() const {
  const auto& score = referee_.score();
  return {{"points", {score[0], score[1]}},
          {"text", std::to_string(score[0]) + "-" + std::to_string(score[1])}};
}

void BasketballMatch::on_time_limit() {
  if (team_play_) write_game_summary();
  end_by_time_limit(leading_team());
}

void BasketballMatch::write_task_observation(int slot, const HeadingFrame& frame,
                                             ObservationWriter& out) const {
  write_ball_observation(*ball_, frame, out);
  const int attacked = team_play_ ? attacked_by(slot) : 0;
  out.begin("rim").field("centre").put(frame.point(config_.court.rim_centre(attacked)));
  if (!team_play_) {
    out.begin("target").field("offset").put(frame.vector(target() - ball_->position()));
    out.begin("throw")
        .field("time_left")
        .put(1.0 - static_cast<double>(tick()) / time_limit_ticks())
        .field("presenting")
        .put(presenting() ? 1.0 : 0.0);
    return;
  }
  const Court& court = config_.court;
  out.begin("arc")
      .field("me")
      .put(court.beyond_arc(frame.root.position.head<2>(), attacked))
      .field("ball")
      .put(court.beyond_arc(ball_->position().head<2>(), attacked));
  write_team_blocks(*this, slot, frame, out);
  const int mine = team_of(slot), with_ball = referee_.possession();
  out.begin("game")
      .field("my_points")
      .put(referee_.score()[mine])
      .field("their_points")
      .put(referee_.score()[1 - mine])
      .field("time_left")
      .put(1.0 - static_cast<double>(tick()) / time_limit_ticks())
      .field("shot_clock")
      .put(referee_.shot_clock_left(time()))
      .field("possession")
      .put(with_ball < 0 ? 0.0 : (with_ball == mine ? 1.0 : -1.0))
      .field("cleared")
      .put(referee_.cleared() ? 1.0 : 0.0)
      .field("presented_to_me")
      .put(presenting() && presented_slot_ == slot ? 1.0 : 0.0);
}

void BasketballMatch::extra_state(std::vector<double>& values) const {
  core::append_body_state(ball_->body(), values);
}

void BasketballMatch::describe_scene(SceneBuilder& scene) const {
  config_.court.describe(scene);
  const int ball = scene.add_body("ball", -1, "ball");
  scene.add_sphere(ball, Eigen::Vector3d::Zero(), ball_->spec().radius, "ball", "#e07a2a");
}

void BasketballMatch::extra_scene_poses(std::vector<float>& out) const {
  append_pose(out, ball_->position(), ball_->orientation());
}

}  // namespace olympics::sports::basketball
