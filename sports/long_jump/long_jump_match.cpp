#include "long_jump/long_jump_match.h"

#include <algorithm>

#include "athletics/competition.h"
#include "core/humanoid_assets.h"
#include "long_jump/long_jump_rewards.h"

namespace olympics::sports::long_jump {
namespace {

const core::ModelSpec& athlete_model() {
  static const core::ModelSpec spec = core::load_humanoid(core::HumanoidKind::Smpl);
  return spec;
}

constexpr double kSandDepth = 0.3;   // m of sand box; its top is kSandProud above the runway
constexpr double kSandProud = 0.02;  // m: the raked sand stands a touch above the runway

}  // namespace

std::vector<LayoutBlock> long_jump_task_layout() {
  return {LayoutBlock::of(
              "take_off_line", "m",
              "the foul line's point on my runway's centre line, relative to the root, heading "
              "frame",
              {{"point", 3}}),
          LayoutBlock::of("goal", "m",
                          "the seed's goal (x = 30, 1 m up) relative to the root, heading frame",
                          {{"position", 3}}),
          LayoutBlock::of("attempt", "flag, fraction, count, m",
                          "a foot is past the line (1/0), share of the attempt's time left, "
                          "attempts left, my best mark so far (0: none)",
                          {{"past_line", 1}, {"time_left", 1}, {"attempts_left", 1}, {"best", 1}})};
}

std::vector<RefereeCall> long_jump_calls() {
  return {{"mark", "a valid jump: mark (m from the foul line to the nearest break), attempt",
           kAnnounced},
          {"foul",
           "a failed attempt: reason (past_the_line, outside_the_pit, fell, time, "
           "left_runway), attempt",
           kAnnounced},
          {"fall", "an athlete fell (body)"}};
}

LongJumpMatch::LongJumpMatch(const LongJumpRules& rules, const ModeSpec& mode, Layout layout,
                             const MatchSettings& settings)
    : SmplMatch(mode, std::move(layout), settings), rules_(rules) {
  for (int slot = 0; slot < slot_count(); ++slot) {
    build_lane(slot);
    add_player(athlete_model(), jittered_start_mark(slot));
    athletes_.push_back({athletics::HorizontalSeries(rules_.attempts), LongJumpReferee(rules_), 0,
                         std::nullopt, player(slot).body_state(0).position});
  }
  feet_ = athletics::foot_bodies(player(0));
}

core::RootPlacement LongJumpMatch::start_mark(int slot) const {
  return {{0.0, lane_y(slot), 0.0}, 0.0};
}

athletics::Footprint LongJumpMatch::pit(int slot) const {
  const double half = 0.5 * rules_.pit_width;
  return {rules_.pit_start(), rules_.pit_end(), lane_y(slot) - half, lane_y(slot) + half};
}

void LongJumpMatch::build_lane(int slot) {
  const athletics::Footprint p = pit(slot);
  const Eigen::Vector3d centre{0.5 * (p.x_lo + p.x_hi), lane_y(slot),
                               kSandProud - 0.5 * kSandDepth};
  const Eigen::Vector3d half{0.5 * rules_.pit_length, 0.5 * rules_.pit_width, 0.5 * kSandDepth};
  dGeomID sand = scene().world().add_static_box(centre, half, 1.0, 0.0);
  core::GeomTag& tag = core::PhysicsWorld::tag_of(sand);
  tag.softness = kSand;
  tag.sensor = true;  // every break in the sand is reported where it is
  pit_tags_.push_back(&tag);
}

JumpStep LongJumpMatch::read_step(int slot) const {
  const core::Humanoid& h = player(slot);
  const auto c =
      athletics::athlete_contacts(scene().world(), h.entity(), pit_tags_[slot], pit(slot));
  JumpStep s;
  s.t = time() - athletes_[slot].attempt_start;
  s.on_ground = c.on_ground;
  s.ground_front_x = c.ground_front_x;
  s.front_x = athletics::foremost_x(h);
  s.feet_front_x = athletics::feet_front_x(h, feet_);
  s.in_pit = c.on_surface;
  s.pit_near_x = c.surface_near_x;
  s.mean_body = athletics::mean_body_position(h);
  s.root_y = h.body_state(0).position.y() - lane_y(slot);
  s.down = down(slot);
  return s;
}

void LongJumpMatch::after_physics_step(double) {
  for (int slot = 0; slot < slot_count(); ++slot) {
    Athlete& a = athletes_[slot];
    if (a.series.done() || a.decided) continue;
    if (auto result = a.referee.step(read_step(slot))) a.decided = *result;
  }
}

void LongJumpMatch::settle_tick() {
  for (int slot = 0; slot < slot_count(); ++slot) {
    Athlete& a = athletes_[slot];
    const Eigen::Vector3d root = player(slot).body_state(0).position;
    LongJumpRewardState r{a.root_prev,
                          root,
                          goal(slot),
                          player(slot).body_state(0).linear_velocity.x(),
                          a.referee.past_line(),
                          false,
                          a.referee.mark()};
    a.root_prev = root;
    if (a.decided) {
      r.landed_this_tick = a.decided->valid;  // r_l: the mark by the rules in force
      r.mark = a.decided->mark;
      a.series.record(*a.decided);
      log(athletics::attempt_call(*a.decided, time(), slot, a.series.taken()));
      a.decided.reset();
      if (!a.series.done()) {  // the next attempt from the start mark
        reset_player(slot, jittered_start_mark(slot));
        a.referee = LongJumpReferee(rules_);
        a.attempt_start = time();
        a.root_prev = player(slot).body_state(0).position;
      }
    }
    const auto terms = long_jump_reward_terms(r);
    set_reward(slot, terms);
    outcome_.scores[slot] = static_cast<float>(a.series.best());
  }
  if (std::all_of(athletes_.begin(), athletes_.end(),
                  [](const Athlete& a) { return a.series.done(); }))
    finish();
}

void LongJumpMatch::finish() {
  athletics::end_horizontal_competition(outcome_, athletics::series_of(athletes_));
}

void LongJumpMatch::on_time_limit() {
  SmplMatch::on_time_limit();
  outcome_.info["places"] = athletics::places(athletics::series_of(athletes_));
}

void LongJumpMatch::write_task_observation(int slot, const HeadingFrame& frame,
                                           ObservationWriter& out) const {
  const Athlete& a = athletes_[slot];
  out.begin("take_off_line").field("point").put(frame.point({rules_.line_x, lane_y(slot), 0.0}));
  out.begin("goal").field("position").put(frame.point(goal(slot)));
  const double t = time() - a.attempt_start;
  out.begin("attempt")
      .field("past_line")
      .put(a.referee.past_line() ? 1.0 : 0.0)
      .field("time_left")
      .put(std::clamp(1.0 - t / rules_.attempt_s, 0.0, 1.0))
      .field("attempts_left")
      .put(static_cast<double>(a.series.attempts() - a.series.taken()))
      .field("best")
      .put(a.series.best());
}

void LongJumpMatch::describe_scene(SceneBuilder& scene) const {
  const double far = rules_.pit_end() + 2;
  scene.set_ground(0.5 * far + 2, 0.5 * slot_count() * rules_.lane_spacing + 4, "#b5653c");
  for (int slot = 0; slot < slot_count(); ++slot) {
    const double y = lane_y(slot), w = 0.5 * rules_.runway_width;
    scene.add_ground_rect(-1.0, rules_.line_x, y - w, y + w, "runway");
    scene.add_box(-1, {rules_.line_x - 0.5 * rules_.board_depth, y, 0.001},
                  {0.5 * rules_.board_depth, w, 0.001}, "take_off_board", "#f4f4f4");
    scene.add_line({rules_.line_x, y - w, 0.003}, {rules_.line_x, y + w, 0.003}, "foul_line");
    const athletics::Footprint p = pit(slot);
    scene.add_box(-1, {0.5 * (p.x_lo + p.x_hi), y, 0.5 * kSandProud},
                  {0.5 * rules_.pit_length, 0.5 * rules_.pit_width, 0.5 * kSandProud}, "sand_pit",
                  "#e2c98f");
  }
}

}  // namespace olympics::sports::long_jump
