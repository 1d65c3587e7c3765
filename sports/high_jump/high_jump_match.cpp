#include "high_jump/high_jump_match.h"

#include <algorithm>
#include <cmath>

#include "athletics/competition.h"
#include "core/humanoid_assets.h"
#include "high_jump/high_jump_rewards.h"

namespace olympics::sports::high_jump {
namespace {

const core::ModelSpec& athlete_model() {
  static const core::ModelSpec spec = core::load_humanoid(core::HumanoidKind::Smpl);
  return spec;
}

}  // namespace

std::vector<LayoutBlock> high_jump_task_layout() {
  return {LayoutBlock::of("bar", "m",
                          "the crossbar's two ends (the arena's -y end, then its +y end) relative "
                          "to the root, heading frame",
                          {{"end_minus_y", 3}, {"end_plus_y", 3}}),
          LayoutBlock::of("goal", "m",
                          "the seed's goal (2 m past the bar, 1 m up) relative to the root",
                          {{"position", 3}}),
          LayoutBlock::of("attempt", "m, count, fraction, m",
                          "the height to clear, tries left at it, share of the attempt's time "
                          "left, my best height so far (0: none)",
                          {{"height", 1}, {"tries_left", 1}, {"time_left", 1}, {"best", 1}})};
}

std::vector<RefereeCall> high_jump_calls() {
  return {{"cleared", "the bar was cleared: height, attempt (jump_off: true in a jump-off)",
           kAnnounced},
          {"failure",
           "a failed attempt: reason (bar_dislodged, touched_beyond, fell, left_area, time, "
           "under_the_bar), "
           "height, attempt",
           kAnnounced},
          {"fall", "an athlete fell (body)"}};
}

HighJumpMatch::HighJumpMatch(const HighJumpRules& rules, const ModeSpec& mode, Layout layout,
                             const MatchSettings& settings)
    : SmplMatch(mode, std::move(layout), settings),
      rules_(rules),
      rounds_(slot_count(), rules_.heights, rules_.tries_per_height, rules_.jump_off_step) {
  for (int slot = 0; slot < slot_count(); ++slot) {
    Athlete a{HighJumpReferee(rules_),
              std::make_unique<Crossbar>(scene().world(), rules_, rules_.bar_x, bar_y(slot),
                                         rules_.heights.front()),
              0.0,
              true,
              std::nullopt,
              Eigen::Vector3d::Zero(),
              Eigen::Vector3d::Zero()};
    athletes_.push_back(std::move(a));
    mat_tags_.push_back(nullptr);
    if (rules_.landing_mat) {
      const athletics::Footprint m = mat(slot);
      dGeomID g = scene().world().add_static_box(
          {0.5 * (m.x_lo + m.x_hi), bar_y(slot), 0.5 * kMatHeight},
          {0.5 * kMatDepth, 0.5 * kMatWidth, 0.5 * kMatHeight}, 1.0, 0.0);
      core::GeomTag& tag = core::PhysicsWorld::tag_of(g);
      tag.softness = kFoam;
      tag.sensor = true;
      mat_tags_.back() = &tag;
    }
    add_player(athlete_model(), jittered_start_mark(slot));
    athletes_.back().root_prev = athletes_.back().reward_root_prev =
        player(slot).body_state(0).position;
  }
}

athletics::Footprint HighJumpMatch::mat(int slot) const {
  const double x0 = rules_.bar_x + kMatGap;
  return {x0, x0 + kMatDepth, bar_y(slot) - 0.5 * kMatWidth, bar_y(slot) + 0.5 * kMatWidth};
}

BarStep HighJumpMatch::read_step(int slot) const {
  const core::Humanoid& h = player(slot);
  const Athlete& a = athletes_[slot];
  const athletics::Footprint none{};
  const auto c = athletics::athlete_contacts(scene().world(), h.entity(), mat_tags_[slot],
                                             mat_tags_[slot] ? mat(slot) : none);
  BarStep s;
  s.t = time() - a.attempt_start;
  s.bar_height = a.bar->height();
  s.bar_in_place = a.bar->in_place();
  s.root = h.body_state(0).position - bar_centre(slot);
  s.root_prev = a.root_prev - bar_centre(slot);
  double min_x = 1e9;
  for (int b = 0; b < h.body_count(); ++b) min_x = std::min(min_x, h.body_state(b).position.x());
  s.min_body_x = min_x - rules_.bar_x;
  s.touched_beyond = c.on_surface || (c.on_ground && c.ground_front_x > rules_.bar_x);
  s.down = down(slot);
  return s;
}

void HighJumpMatch::after_physics_step(double) {
  for (int slot = 0; slot < slot_count(); ++slot) {
    Athlete& a = athletes_[slot];
    if (!a.in_attempt || a.decided) continue;
    if (auto d = a.referee.step(read_step(slot))) a.decided = *d;
    a.root_prev = player(slot).body_state(0).position;
  }
}

void HighJumpMatch::settle_tick() {
  bool recorded = false;
  for (int slot = 0; slot < slot_count(); ++slot) {
    Athlete& a = athletes_[slot];
    const Eigen::Vector3d root = player(slot).body_state(0).position;
    const auto terms = high_jump_reward_terms(a.reward_root_prev, root, goal(slot), rules_.bar_x);
    a.reward_root_prev = root;
    set_reward(slot, terms);
    if (a.decided) {
      record_attempt(slot);
      recorded = true;
    }
    outcome_.scores[slot] = static_cast<float>(rounds_.series(slot).best());
  }
  if (recorded)  // a try round may be over: the next tries, at the bar's height now, in slot order
    for (int slot = 0; slot < slot_count(); ++slot)
      if (rounds_.due(slot) && !athletes_[slot].in_attempt) start_attempt(slot);
  if (rounds_.over()) finish();
}

void HighJumpMatch::record_attempt(int slot) {
  Athlete& a = athletes_[slot];
  const double height = a.bar->height();
  const bool jump_off = rounds_.in_jump_off();
  rounds_.record(slot, a.decided->cleared);
  nlohmann::json e = referee_event(a.decided->cleared ? "cleared" : "failure", time(), slot);
  e["height"] = height;
  e["attempt"] = rounds_.series(slot).attempts();
  if (jump_off) e["jump_off"] = true;
  if (!a.decided->cleared) e["reason"] = a.decided->reason;
  log(std::move(e));
  a.decided.reset();
  a.in_attempt = false;
}

// The next attempt: the bar at the competition's height, the athlete back to its mark.
void HighJumpMatch::start_attempt(int slot) {
  Athlete& a = athletes_[slot];
  a.bar->set(rounds_.bar_height());
  reset_player(slot, jittered_start_mark(slot));
  a.referee = HighJumpReferee(rules_);
  a.attempt_start = time();
  a.root_prev = a.reward_root_prev = player(slot).body_state(0).position;
  a.in_attempt = true;
}

void HighJumpMatch::finish() {
  std::vector<float> best;
  for (const auto& s : rounds_.all_series()) best.push_back(static_cast<float>(s.best()));
  athletics::end_competition(outcome_, rounds_.places(), best, "series_complete");
}

void HighJumpMatch::on_time_limit() {
  SmplMatch::on_time_limit();
  outcome_.info["places"] = rounds_.places();  // the countback's: an unfinished jump-off shares
}

void HighJumpMatch::write_task_observation(int slot, const HeadingFrame& frame,
                                           ObservationWriter& out) const {
  const Athlete& a = athletes_[slot];
  out.begin("bar")
      .field("end_minus_y")
      .put(frame.point(a.bar->end(-1)))
      .field("end_plus_y")
      .put(frame.point(a.bar->end(1)));
  out.begin("goal").field("position").put(frame.point(goal(slot)));
  const double t = time() - a.attempt_start;
  out.begin("attempt")
      .field("height")
      .put(rounds_.bar_height())
      .field("tries_left")
      .put(rounds_.in_jump_off() ? 1.0
                                 : static_cast<double>(rounds_.series(slot).tries_left_at_height()))
      .field("time_left")
      .put(std::clamp(1.0 - t / rules_.attempt_s, 0.0, 1.0))
      .field("best")
      .put(rounds_.series(slot).best());
}

void HighJumpMatch::extra_state(std::vector<double>& values) const {
  for (const auto& a : athletes_) {
    const dBodyID b = a.bar->body();
    for (const dReal* v : {dBodyGetPosition(b), dBodyGetLinearVel(b), dBodyGetAngularVel(b)})
      values.insert(values.end(), v, v + 3);
    const dReal* q = dBodyGetQuaternion(b);
    values.insert(values.end(), q, q + 4);
  }
}

void HighJumpMatch::describe_scene(SceneBuilder& scene) const {
  double half_y = rules_.bar_y + slot_count() * rules_.lane_spacing + 4;
  if (rules_.official)  // the run-up fans reach runup_radius to either side of the bars
    half_y = std::max(
        half_y, rules_.bar_y + (slot_count() - 1) * rules_.lane_spacing + rules_.runup_radius + 1);
  scene.set_ground(rules_.bar_x + 8, half_y, "#b5653c");
  for (int slot = 0; slot < slot_count(); ++slot) {
    if (rules_.landing_mat) {
      const athletics::Footprint m = mat(slot);
      scene.add_box(-1, {0.5 * (m.x_lo + m.x_hi), bar_y(slot), 0.5 * kMatHeight},
                    {0.5 * kMatDepth, 0.5 * kMatWidth, 0.5 * kMatHeight}, "landing_mat", "#2f5fa8");
    }
    if (rules_.official) {  // the run-up fan: its arc in 32 chords, and the bar's plane
      constexpr int kChords = 32;
      const Eigen::Vector3d c = bar_centre(slot);
      auto on_arc = [&](int i) {
        const double a = M_PI / 2 + M_PI * i / kChords;  // from the left round to the right
        return Eigen::Vector3d(c.x() + rules_.runup_radius * std::cos(a),
                               c.y() + rules_.runup_radius * std::sin(a), 0.002);
      };
      for (int i = 0; i < kChords; ++i) scene.add_line(on_arc(i), on_arc(i + 1), "runup");
      scene.add_line(on_arc(0), on_arc(kChords), "runup");
    }
    for (int side : {-1, 1}) {
      const Eigen::Vector3d foot{rules_.bar_x, bar_y(slot) + side * 0.5 * rules_.upright_gap, 0};
      scene.add_segment(-1, "cylinder", foot, foot + Eigen::Vector3d(0, 0, 2.7), 0.02, "upright",
                        "#d8d8d8");
    }
  }
  for (int slot = 0; slot < slot_count(); ++slot) {
    const int body = scene.add_body("crossbar_" + std::to_string(slot), -1, "crossbar");
    const double half = 0.5 * rules_.bar_length;
    scene.add_segment(body, "cylinder", {0, 0, -half}, {0, 0, half}, rules_.bar_radius, "crossbar",
                      "#e8e8e8");
  }
}

void HighJumpMatch::extra_scene_poses(std::vector<float>& out) const {
  for (const auto& a : athletes_) append_pose(out, a.bar->position(), a.bar->orientation());
}

}  // namespace olympics::sports::high_jump
