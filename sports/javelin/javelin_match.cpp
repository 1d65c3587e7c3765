#include "javelin/javelin_match.h"

#include <algorithm>
#include <cmath>

#include "athletics/competition.h"
#include "core/humanoid_assets.h"
#include "core/state_hash.h"
#include "framework/jittered_start.h"
#include "javelin/javelin_rewards.h"

namespace olympics::sports::javelin {
namespace {

const core::ModelSpec& athlete_model() {
  static const core::ModelSpec spec = core::load_humanoid(kHumanoid);
  return spec;
}

constexpr double kSectorDrawn = 100.0;  // m of sector line drawn for viewers

}  // namespace

std::vector<LayoutBlock> javelin_task_layout() {
  return {LayoutBlock::of("javelin", "m, m/s, flag",
                          "my javelin: its cord and its tip relative to the root, its velocity, "
                          "its axis (unit, tail to tip), all in the heading frame; held (1) or "
                          "not (0)",
                          {{"cord", 3}, {"tip", 3}, {"velocity", 3}, {"axis", 3}, {"held", 1}}),
          LayoutBlock::of("field", "m",
                          "the arc's inner edge on my runway's axis and the seed's target "
                          "(50 m from my start mark along the runway), relative to the root, "
                          "heading frame",
                          {{"arc", 3}, {"target", 3}}),
          LayoutBlock::of("attempt", "stage, fraction, count, m",
                          "the seed's stage (0 hold, 1 throw, 2 flight), share of the attempt's "
                          "time left, attempts left, my best mark so far (0: none)",
                          {{"stage", 1}, {"time_left", 1}, {"attempts_left", 1}, {"best", 1}})};
}

std::vector<RefereeCall> javelin_calls() {
  return {{"mark", "a valid throw: mark (m from the arc, or paper's x), attempt", kAnnounced},
          {"foul",
           "a failed attempt: reason (flat, sector, arc, runway, fell, time; paper: dropped, "
           "strayed, not_thrown), attempt",
           kAnnounced},
          {"release", "the fingers opened and the javelin left the hand (speed m/s, angle deg)"},
          {"fall", "an athlete fell (body)"}};
}

JavelinMatch::JavelinMatch(const JavelinRules& rules, const ModeSpec& mode, Layout layout,
                           const MatchSettings& settings)
    : SmplMatch(mode, std::move(layout), settings), rules_(rules) {
  for (int slot = 0; slot < slot_count(); ++slot) {
    add_player(athlete_model(), start_mark(slot));
    athletes_.emplace_back(rules_.attempts, JavelinReferee(rules_, area(slot), 0.0),
                           std::make_unique<Javelin>(scene().world(), rules_.javelin),
                           ThrowingHand(player(slot)));
    begin_attempt(slot);
  }
}

ThrowingArea JavelinMatch::area(int slot) const {
  return {{rules_.run_up - rules_.arc_radius, lane_y(slot)},
          rules_.arc_radius,
          rules_.half_sector_rad(),
          0.5 * rules_.runway_width};
}

Eigen::Quaterniond JavelinMatch::default_attitude() const {
  return Eigen::Quaterniond(
      Eigen::AngleAxisd(-rules_.default_pitch_deg * M_PI / 180.0, Eigen::Vector3d::UnitY()));
}

void JavelinMatch::begin_attempt(int slot) {
  Athlete& a = athletes_[slot];
  core::Humanoid& h = player(slot);
  // On its mark, moved and turned a little by the match's random stream (so that seeds differ).
  const core::RootPlacement mark = start_mark(slot);
  reset_player(slot, jittered_start(mark.position.head<2>(), mark.yaw, rng()));
  a.javelin->release();
  a.javelin->place(a.hand.cord_point(h), default_attitude());
  a.javelin->grip(h.ode_body(a.hand.palm()), a.hand.geoms(h));
  a.referee = JavelinReferee(rules_, area(slot), start_mark(slot).position.x());
  a.attempt_start = time();
  a.attempt_tick = tick();
  a.present_until = time() + rules_.present_s;
  a.cord_start = a.javelin->grip_point();
  a.root_start = h.body_state(0).position.head<2>();
  a.javelin_x_prev = a.javelin->centre().x();
}

void JavelinMatch::before_physics_step() {
  for (int slot = 0; slot < slot_count(); ++slot) {
    Athlete& a = athletes_[slot];
    if (rules_.aerodynamics) a.javelin->add_aerodynamic_load();
    if (!a.javelin->held() || time() < a.present_until) continue;
    if (a.hand.finger_flexion(player(slot)) >= rules_.grip_closed) continue;
    a.javelin->release();  // the fingers opened
    const Eigen::Vector3d v = a.javelin->velocity();
    nlohmann::json e = referee_event("release", time(), slot);
    e["speed"] = v.norm();
    e["angle"] = std::atan2(v.z(), v.head<2>().norm()) * 180.0 / M_PI;
    log(std::move(e));
  }
}

ThrowStep JavelinMatch::read_step(int slot) const {
  const Athlete& a = athletes_[slot];
  const Javelin& j = *a.javelin;
  const core::Humanoid& h = player(slot);
  const ThrowingArea field = area(slot);
  ThrowStep s;
  s.t = time() - a.attempt_start;
  s.tick = attempt_tick(slot);
  s.held = j.held();
  s.head_only = true;
  double nearest_tip = 1e9;
  for (const auto& g : scene().world().ground_contacts()) {
    if (g.geom->entity == j.entity()) {
      s.javelin_ground = true;
      if (g.geom->geom != Javelin::kHeadGeom) {
        s.head_only = false;
      } else if (const double d = (g.position - j.tip()).norm(); d < nearest_tip) {
        nearest_tip = d;  // of the head's points, the one nearest its tip
        s.tip_touch = g.position;
      }
    } else if (g.geom->entity == h.entity()) {
      s.athlete_beyond_arc = s.athlete_beyond_arc || field.beyond_arc(g.position);
      s.athlete_outside_runway = s.athlete_outside_runway || field.outside_runway(g.position);
    }
  }
  s.javelin_centre = j.centre();
  s.hand_distance = (j.grip_point() - h.body_state(a.hand.palm()).position).norm();
  s.attitude_error = j.orientation().angularDistance(default_attitude());
  s.down = down(slot);
  return s;
}

void JavelinMatch::after_physics_step(double) {
  for (int slot = 0; slot < slot_count(); ++slot) {
    Athlete& a = athletes_[slot];
    if (a.series.done() || a.decided) continue;
    if (auto result = a.referee.step(read_step(slot))) a.decided = *result;
  }
}

void JavelinMatch::settle_tick() {
  for (int slot = 0; slot < slot_count(); ++slot) {
    Athlete& a = athletes_[slot];
    const Javelin& j = *a.javelin;
    const core::Humanoid& h = player(slot);
    const Eigen::Vector3d start = start_mark(slot).position;
    JavelinRewardState r;
    r.stage = stage_at(rules_, attempt_tick(slot) - 1);  // the tick just played
    r.cord = j.grip_point();
    r.hand = h.body_state(a.hand.palm()).position;
    r.cord_start = a.cord_start;
    r.attitude_error = j.orientation().angularDistance(default_attitude());
    r.velocity = j.velocity();
    r.spin = j.spin();
    r.root_offset = h.body_state(0).position.head<2>() - a.root_start;
    r.x_prev = a.javelin_x_prev - start.x();
    r.x = j.centre().x() - start.x();
    r.target_x = rules_.target_x;
    const Eigen::Vector2d to_target =
        Eigen::Vector2d(start.x() + rules_.target_x, lane_y(slot)) - j.centre().head<2>();
    const Eigen::Vector2d axis = j.axis().head<2>();
    r.heading_err = axis.norm() < 1e-9
                        ? 0.0
                        : std::abs(std::atan2(axis.x() * to_target.y() - axis.y() * to_target.x(),
                                              axis.dot(to_target)));
    a.javelin_x_prev = j.centre().x();
    set_reward(slot, javelin_reward_terms(r));
    if (a.decided) {
      a.series.record(*a.decided);
      log(athletics::attempt_call(*a.decided, time(), slot, a.series.taken()));
      a.decided.reset();
      if (!a.series.done()) begin_attempt(slot);
    }
    outcome_.scores[slot] = static_cast<float>(a.series.best());
  }
  if (std::all_of(athletes_.begin(), athletes_.end(),
                  [](const Athlete& a) { return a.series.done(); }))
    finish();
}

void JavelinMatch::finish() {
  athletics::end_horizontal_competition(outcome_, athletics::series_of(athletes_));
}

void JavelinMatch::on_time_limit() {
  SmplMatch::on_time_limit();
  outcome_.info["places"] = athletics::places(athletics::series_of(athletes_));
}

void JavelinMatch::write_task_observation(int slot, const HeadingFrame& frame,
                                          ObservationWriter& out) const {
  const Athlete& a = athletes_[slot];
  const Javelin& j = *a.javelin;
  out.begin("javelin")
      .field("cord")
      .put(frame.point(j.grip_point()))
      .field("tip")
      .put(frame.point(j.tip()))
      .field("velocity")
      .put(frame.vector(j.velocity()))
      .field("axis")
      .put(frame.vector(j.axis()))
      .field("held")
      .put(j.held() ? 1.0 : 0.0);
  const Eigen::Vector3d start = start_mark(slot).position;
  out.begin("field")
      .field("arc")
      .put(frame.point({rules_.run_up, lane_y(slot), 0.0}))
      .field("target")
      .put(frame.point({start.x() + rules_.target_x, lane_y(slot), 0.0}));
  const double t = time() - a.attempt_start;
  out.begin("attempt")
      .field("stage")
      .put(static_cast<double>(stage_at(rules_, attempt_tick(slot))))
      .field("time_left")
      .put(std::clamp(1.0 - t / rules_.attempt_s, 0.0, 1.0))
      .field("attempts_left")
      .put(static_cast<double>(a.series.attempts() - a.series.taken()))
      .field("best")
      .put(a.series.best());
}

void JavelinMatch::describe_scene(SceneBuilder& scene) const {
  scene.set_ground(kSectorDrawn + 10, 0.5 * slot_count() * rules_.lane_spacing + 30, "#5d7d4a");
  for (int slot = 0; slot < slot_count(); ++slot) {
    const ThrowingArea field = area(slot);
    const double y = lane_y(slot), w = field.runway_half_width;
    const double end_x = field.centre.x() + std::sqrt(field.radius * field.radius - w * w);
    scene.add_ground_rect(-1.0, end_x, y - w, y + w, "runway");
    constexpr int kArcSegments = 12;
    for (int i = 0; i < kArcSegments; ++i) {  // the arc, between the runway lines
      auto at = [&](int k) {
        const double phi = -field.half_angle + 2.0 * field.half_angle * k / kArcSegments;
        return Eigen::Vector3d(field.centre.x() + field.radius * std::cos(phi),
                               y + field.radius * std::sin(phi), 0.003);
      };
      scene.add_line(at(i), at(i + 1), "arc");
    }
    for (double side : {-1.0, 1.0}) {
      const Eigen::Vector3d c(field.centre.x(), y, 0.003);
      const Eigen::Vector3d d(std::cos(field.half_angle), side * std::sin(field.half_angle), 0);
      scene.add_line(c + field.radius * d, c + kSectorDrawn * d, "sector_line");
    }
  }
  const JavelinSpec& js = rules_.javelin;
  for (int slot = 0; slot < slot_count(); ++slot) {
    const int body = scene.add_body("javelin", slot, "javelin");
    const Eigen::Vector3d tip(js.tip_to_com, 0, 0), head_end(js.tip_to_com - js.head_length, 0, 0),
        tail(js.tip_to_com - js.length, 0, 0);
    scene.add_segment(body, "capsule", head_end, tip, js.head_radius, "javelin_head", "#c0c0c0");
    scene.add_segment(body, "capsule", tail, head_end, js.radius, "javelin_shaft", "#d8d040");
  }
}

void JavelinMatch::extra_scene_poses(std::vector<float>& out) const {
  for (const auto& a : athletes_) append_pose(out, a.javelin->centre(), a.javelin->orientation());
}

void JavelinMatch::extra_state(std::vector<double>& values) const {
  for (const auto& a : athletes_) {
    core::append_body_state(a.javelin->body(), values);
    values.push_back(a.javelin->held() ? 1.0 : 0.0);
  }
}

}  // namespace olympics::sports::javelin
