#include "fencing/fencing_match.h"

#include <cmath>

#include "combat/combat_observation.h"
#include "combat/combat_rewards.h"
#include "combat/start_placement.h"
#include "core/humanoid_assets.h"
#include "fencing/epee.h"

namespace olympics::sports::fencing {
namespace {

// A tip held on a target is one hit, not one per physics step.
constexpr double kHitRefractoryS = 0.1;

}  // namespace

const core::ModelSpec& fencer_model() {
  static const core::ModelSpec spec = [] {
    core::ModelSpec s = core::load_humanoid(core::HumanoidKind::Smpl);
    equipment::attach_equipment(s, epee());
    return s;
  }();
  return spec;
}

std::vector<LayoutBlock> fencing_task_layout() {
  std::vector<LayoutBlock> blocks = combat::opponent_blocks();
  const std::vector<FieldSize> tip = {{"position", 3}, {"velocity", 3}};
  blocks.push_back(LayoutBlock::of(
      "tip", "m, m/s",
      "my épée's tip: position relative to the root (3), velocity (3), heading frame", tip));
  blocks.push_back(
      LayoutBlock::of("opponent_tip", "m, m/s", "the opponent's épée's tip, likewise", tip));
  blocks.push_back(LayoutBlock::of(
      "piste", "m",
      "root along the piste towards the opponent's end and across it (left positive), from my "
      "side; distances to my end and to the opponent's end",
      {{"along", 1}, {"across", 1}, {"to_my_end", 1}, {"to_their_end", 1}}));
  blocks.push_back(
      LayoutBlock::of("bout", "touches, fraction",
                      "my touches, the opponent's touches, share of the bout's time left",
                      {{"my_touches", 1}, {"their_touches", 1}, {"time_left", 1}}));
  return blocks;
}

std::vector<RefereeCall> fencing_calls() {
  return {{"hit", "a tip met a valid target with enough force (slot, target_slot, body, force_n)"},
          {"point", "a touch scores for slot (reason: touch, double, fall)", kAnnounced},
          {"halt",
           "play stopped without a score (reason: off_piste, fall, idle, double_annulled; "
           "culprit_slot)",
           kAnnounced},
          {"fall", "a fencer fell (body)"}};
}

FencingMatch::FencingMatch(const FencingConfig& config, const ModeSpec& mode, Layout layout,
                           const MatchSettings& settings)
    : SmplMatch(mode, std::move(layout), settings), config_(config), referee_(config.rules) {
  const core::ModelSpec& spec = fencer_model();
  hand_body_ = spec.body_index("R_Hand");
  hand_own_geoms_ = static_cast<int>(spec.bodies[hand_body_].geoms.size()) - epee_geom_count();
  targets_ = combat::target_body_indices(spec);
  ankles_ = {spec.body_index("L_Ankle"), spec.body_index("R_Ankle")};
  // The hand holding the épée may touch the ground, as a racket hand may.
  for (int f = 0; f < 2; ++f) add_player(spec, on_guard(f), {"R_Hand"});

  std::vector<bool> is_target(spec.bodies.size(), config_.whole_body);
  for (int b : targets_) is_target[b] = true;
  const int hand = hand_body_, own = hand_own_geoms_;
  touches_.emplace(
      std::vector<int>{player(0).entity(), player(1).entity()}, teams(),
      [is_target, hand, own](int body, int geom) {
        return is_target[body] && !(body == hand && geom >= own);  // not the épée
      },
      config_.touch_force_n, /*refractory_s=*/0.0);
  referee_.next_exchange(0.0);
}

Eigen::Vector3d FencingMatch::tip_position(int slot) const {
  return combat::point_on_body(player(slot).body_state(hand_body_), kTipInHand).position;
}

void FencingMatch::after_physics_step(double) {
  for (const Touch& t : touches_->collect(scene().world(), time())) {
    nlohmann::json hit = referee_event("hit", time(), t.attacker);
    hit["target_slot"] = t.defender;
    hit["body"] = player(t.defender).spec().bodies[t.target_body].name;
    hit["force_n"] = tenths(t.force);
    log(std::move(hit));
    referee_.touch(teams()[t.attacker], time());
  }
  referee_.update(time());
}

void FencingMatch::settle_tick() {
  const GroundRect piste = config_.piste.area();
  std::array<bool, 2> off{}, fallen{};
  for (int f = 0; f < 2; ++f) {
    off[f] = any_body_outside(player(f), piste, ankles_);
    fallen[f] = down(f);
  }
  referee_.falls(fallen, time());
  referee_.off_piste(off, time());
  referee_.update(time());

  const auto& halt = referee_.halt();
  for (int f = 0; f < 2; ++f) {
    combat::CombatRewardInput in;
    in.root = player(f).body_state(0);
    in.opponent_root = player(1 - f).body_state(0).position;
    in.strikers = {tip_position(f)};
    for (int b : targets_) in.targets.push_back(player(1 - f).body_state(b).position);
    in.scored = halt && halt->scored[f];
    set_reward(f, combat::combat_reward_terms(in));
  }
  const auto& s = referee_.score();
  outcome_.scores = {static_cast<float>(s[0]), static_cast<float>(s[1])};
  outcome_.info["score"] = score_json();
  if (!halt) return;
  record_halt(*halt);
  if (referee_.bout_over()) {
    outcome_.info["exchanges"] = exchanges_;
    return outcome_.end("bout_won", referee_.winner());
  }
  back_on_guard();
}

void FencingMatch::record_halt(const Halt& halt) {
  bool any = false;
  for (int f = 0; f < 2; ++f) {
    if (!halt.scored[f]) continue;
    any = true;
    nlohmann::json point = referee_event("point", halt.time, f);
    point["reason"] = halt.reason;
    log(std::move(point));
  }
  if (!any) {
    nlohmann::json stop = referee_event("halt", halt.time);
    stop["reason"] = halt.reason;
    stop["culprit_slot"] = halt.culprit;
    log(std::move(stop));
  }
  exchanges_.push_back({{"n", exchanges_.size() + 1},
                        {"reason", halt.reason},
                        {"scored", {halt.scored[0], halt.scored[1]}},
                        {"culprit_slot", halt.culprit},
                        {"tick", tick()},
                        {"score", score_json()["text"]}});
}

core::RootPlacement FencingMatch::on_guard(int fencer) {
  return combat::jittered_start(fencer, config_.piste.on_guard, rng());
}

void FencingMatch::back_on_guard() {
  for (int f = 0; f < 2; ++f) reset_player(f, on_guard(f));
  touches_->reset();
  referee_.next_exchange(time());
}

nlohmann::json FencingMatch::score_json() const {
  const auto& s = referee_.score();
  return {{"touches", {s[0], s[1]}},
          {"text", std::to_string(s[0]) + "-" + std::to_string(s[1])},
          {"to_win", config_.rules.touches}};
}

void FencingMatch::on_time_limit() {
  outcome_.info["exchanges"] = exchanges_;
  end_by_time_limit(leading_team());
}

void FencingMatch::write_task_observation(int slot, const HeadingFrame& frame,
                                          ObservationWriter& out) const {
  const int other = 1 - slot;
  combat::write_opponent_blocks(frame, player(other), targets_, out);
  for (const auto& [block, who] : {std::pair{"tip", slot}, std::pair{"opponent_tip", other}}) {
    const auto tip = combat::point_on_body(player(who).body_state(hand_body_), kTipInHand);
    out.begin(block)
        .field("position")
        .put(frame.point(tip.position))
        .field("velocity")
        .put(frame.vector(tip.velocity));
  }
  const double side = -combat::side(slot);  // +1: my end is at -x
  const double along = frame.root.position.x() * side, across = frame.root.position.y() * side;
  const double half = config_.piste.length / 2;
  out.begin("piste")
      .field("along")
      .put(along)
      .field("across")
      .put(across)
      .field("to_my_end")
      .put(along + half)
      .field("to_their_end")
      .put(half - along);
  const auto& s = referee_.score();
  out.begin("bout")
      .field("my_touches")
      .put(s[slot])
      .field("their_touches")
      .put(s[other])
      .field("time_left")
      .put(1.0 - static_cast<double>(tick()) / time_limit_ticks());
}

}  // namespace olympics::sports::fencing
