#include "golf/golf_match.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "athletics/competition.h"
#include "core/humanoid_assets.h"
#include "core/state_hash.h"
#include "golf/golf_rewards.h"

namespace olympics::sports::golf {
namespace {

const char* kHand = "R_Hand";

core::ModelSpec equip(const ClubSpec& club) {
  core::ModelSpec s = core::load_humanoid(core::HumanoidKind::Smpl);
  equipment::attach_equipment(s, club_equipment(club));
  return s;
}

// The humanoid holding `club` (built once per club kind: matches are made on many threads).
const core::ModelSpec& golfer_model(const ClubSpec& club) {
  static const core::ModelSpec with_putter = equip(putter());
  static const core::ModelSpec with_driver = equip(driver());
  static const core::ModelSpec with_seed_club = equip(seed_club());
  if (club.name == "putter") return with_putter;
  if (club.name == "driver") return with_driver;
  if (club.name == "seed_club") return with_seed_club;
  throw std::invalid_argument("golf: no club \"" + club.name +
                              "\"; clubs: putter, driver, seed_club");
}

constexpr double kSeedContactM = 0.2;       // the seed's club-ball contact distance
constexpr double kSeedContactMoved = 0.01;  // m the ball must have moved in x
constexpr double kSeedNearBodyM = 0.15;

}  // namespace

equipment::BallSpec rules_golf_ball() {
  equipment::BallSpec b = equipment::golf_ball();
  b.restitution = 0.1;
  b.friction = 1.0;
  return b;
}

std::vector<LayoutBlock> golf_task_layout() {
  return {LayoutBlock::of("ball", "m, m/s", "my ball relative to the root, heading frame",
                          {{"position", 3}, {"velocity", 3}}),
          LayoutBlock::of("club_head", "m", "my club head's centre relative to the root",
                          {{"position", 3}}),
          LayoutBlock::of("target", "m",
                          "the hole (official) or the seed's target (paper) relative to the root, "
                          "heading frame",
                          {{"position", 3}}),
          LayoutBlock::of("play", "count, flag, fraction",
                          "strokes taken (penalties included), the club has struck the ball in "
                          "this stroke (1/0), share of the hole's time left",
                          {{"strokes", 1}, {"contact", 1}, {"time_left", 1}})};
}

std::vector<RefereeCall> golf_calls() {
  return {{"stroke", "the athlete's club struck its ball: stroke (number)", kAnnounced},
          {"at_rest", "the ball came to rest off the hole: distance (m to the hole)"},
          {"out_of_bounds", "the ball left the lane: a penalty stroke, replayed from its lie",
           kAnnounced},
          {"holed", "the ball is in the hole: strokes, score", kAnnounced},
          {"picked_up", "the hole is over without holing out: reason (max_strokes, time), score",
           kAnnounced},
          {"shot_end",
           "paper: the seed's episode ended: reason (ball_stopped, fell, ball_near_body, "
           "ball_not_closer, no_contact), hit, stop_distance, success",
           kAnnounced},
          {"fall", "an athlete fell (body)"}};
}

GolfMatch::GolfMatch(const GolfRules& rules, const ModeSpec& mode, Layout layout,
                     const MatchSettings& settings)
    : SmplMatch(mode, std::move(layout), settings), rules_(rules) {
  const core::ModelSpec& model = golfer_model(rules_.club);
  hand_body_ = model.body_index(kHand);
  club_geoms_from_ = static_cast<int>(model.bodies[hand_body_].geoms.size()) - 2;
  green_c_rr_ = rolling_resistance_for_stimp(rules_.green_stimp);
  fairway_c_rr_ = rolling_resistance_for_stimp(rules_.fairway_stimp);
  const double fall = rules_.green_fall_deg * M_PI / 180;  // the lanes run along +x
  slope_ = {{std::cos(fall), std::sin(fall), 0.0}, rules_.green_slope / 100};
  const equipment::BallSpec ball = rules_golf_ball();
  for (int slot = 0; slot < slot_count(); ++slot) {
    Athlete a{nullptr,
              nullptr,
              lane_origin(slot),
              {},
              {},
              {},
              HoleReferee(rules_),
              {},
              0,
              0,
              false,
              0,
              false,
              {},
              {}};
    const Eigen::Vector3d at = a.origin + Eigen::Vector3d(0, 0, ball.radius);
    a.ball = std::make_unique<equipment::Ball>(scene().world(), ball, at);
    a.ball->sense_contacts();
    if (rules_.official) {
      a.target = a.origin + Eigen::Vector3d(rules_.distance, 0, 0);
      a.hole = std::make_unique<Hole>(
          scene().world(), HoleSpec{a.target.head<2>(), rules_.hole_radius, rules_.hole_depth});
    } else {  // the seed's target: to the left of an athlete facing -x, 0 to max_target away
      const double d = std::uniform_real_distribution<double>(0, rules_.max_target)(rng());
      a.target = a.origin + Eigen::Vector3d(0, -d, 0);
    }
    a.ball_prev = a.lie = at;
    athletes_.push_back(std::move(a));
    add_player(model, address(athletes_.back()), {kHand});
  }
  // The club head's restitution (the ball's own is the turf's 0.1; a pair takes the larger).
  for (int slot = 0; slot < slot_count(); ++slot)
    for (dGeomID g = dBodyGetFirstGeom(player(slot).ode_body(hand_body_)); g;
         g = dBodyGetNextGeom(g)) {
      core::GeomTag& tag = core::PhysicsWorld::tag_of(g);
      if (tag.geom >= club_geoms_from_) tag.restitution = rules_.club.restitution;
    }
}

Eigen::Vector3d GolfMatch::lane_origin(int slot) const {
  // Paper targets lie along -y of the ball, so its lanes stand side by side along x.
  return rules_.official ? Eigen::Vector3d(0, slot * rules_.lane_spacing, 0)
                         : Eigen::Vector3d(slot * rules_.lane_spacing, 0, 0);
}

core::RootPlacement GolfMatch::address(const Athlete& a) const {
  if (!rules_.official)  // the seed's: 1 m from the ball in +x, facing it
    return {a.origin + Eigen::Vector3d(1, 0, 0), M_PI};
  Eigen::Vector2d u = (a.target - a.lie).head<2>();
  u = u.norm() > 1e-6 ? Eigen::Vector2d(u.normalized()) : Eigen::Vector2d(1, 0);
  const Eigen::Vector2d left(-u.y(), u.x());
  const Eigen::Vector2d root =
      a.lie.head<2>() + rules_.address_side * left - rules_.address_ahead * u;
  return {{root.x(), root.y(), 0.0}, std::atan2(u.y(), u.x())};
}

Eigen::Vector3d GolfMatch::club_head(int slot) const {
  const core::BodyState hand = player(slot).body_state(hand_body_);
  return hand.position + hand.orientation * club_head_offset(rules_.club);
}

equipment::Pose GolfMatch::club_head_pose(int slot) const {
  const core::BodyState hand = player(slot).body_state(hand_body_);
  return golf::club_head_pose(rules_.club, {hand.position, hand.orientation});
}

bool GolfMatch::on_green(const Athlete& a) const {
  if (!rules_.official) return false;  // the seed's ground: fairway
  return (a.ball->position() - a.target).head<2>().norm() < rules_.green_radius;
}

void GolfMatch::before_physics_step() {
  const double dt = scene().settings().physics_dt();
  for (int slot = 0; slot < slot_count(); ++slot) {
    Athlete& a = athletes_[slot];
    a.ball->set_rolling_resistance(on_green(a) ? green_c_rr_ : fairway_c_rr_);
    if (a.hole) a.hole->before_step(*a.ball);
    a.ball->prepare_step(dt);
    if (on_green(a)) {
      const Eigen::Vector3d pull = slope_force(*a.ball, slope_);
      dBodyAddForce(a.ball->body(), pull.x(), pull.y(), pull.z());
    }
    a.head_before = club_head_pose(slot);
    a.ball_before = a.ball->position();
  }
}

void GolfMatch::after_physics_step(double step_start) {
  std::vector<char> solver_struck(slot_count(), 0);
  for (const auto& c : scene().world().sensed_contacts()) {
    if (!c.sensor || !c.other) continue;
    for (int slot = 0; slot < slot_count(); ++slot) {
      if (c.sensor->entity != athletes_[slot].ball->entity()) continue;
      solver_struck[slot] |= c.other->entity == player(slot).entity() &&
                             c.other->body == hand_body_ && c.other->geom >= club_geoms_from_;
    }
  }
  const double dt = scene().settings().physics_dt();
  for (int slot = 0; slot < slot_count(); ++slot) {
    Athlete& a = athletes_[slot];
    bool struck = solver_struck[slot] != 0;
    if (!struck) {  // a head too fast for the solver's contacts (swept_strike.h)
      const auto strike = find_swept_strike(rules_.club, a.head_before, club_head_pose(slot),
                                            a.ball_before, *a.ball, dt);
      if (strike) {
        apply_swept_strike(*strike, *a.ball, player(slot).ode_body(hand_body_), dt);
        struck = true;
      }
    }
    if (struck && !a.touched) {
      a.touched = true;
      a.touched_t = step_start - a.start;
    }
  }
}

bool GolfMatch::body_near_ball(int slot) const {
  const core::Humanoid& h = player(slot);
  const Eigen::Vector3d ball = athletes_[slot].ball->position();
  for (int b = 0; b < h.body_count(); ++b)
    if (b != hand_body_ && (h.body_state(b).position - ball).norm() < kSeedNearBodyM) return true;
  return false;
}

GolfTick GolfMatch::read_tick(int slot) const {
  const Athlete& a = athletes_[slot];
  GolfTick s;
  s.tick = tick() - a.start_tick;
  s.t = time() - a.start;
  s.ball = a.ball->position() - a.origin;
  s.ball_prev = a.ball_prev - a.origin;
  s.ball_speed = a.ball->velocity().norm();
  s.club_touch = a.touched;
  s.club_touch_t = a.touched_t;
  s.target = a.target - a.origin;
  if (a.hole) s.holed = a.hole->holds(a.ball->position(), a.ball->spec().radius);
  const Eigen::Vector3d along = a.target - a.origin;
  const double beyond = s.ball.dot(along.normalized()) - along.norm();
  s.out_of_bounds = std::abs(s.ball.y()) > rules_.lane_half_width ||
                    s.ball.x() < -rules_.lane_half_width || beyond > 2 * rules_.lane_half_width;
  s.seed_contact = (a.ball->position() - club_head(slot)).norm() < kSeedContactM &&
                   std::abs(s.ball.x()) > kSeedContactMoved;
  s.body_near_ball = body_near_ball(slot);
  s.down = down(slot);
  return s;
}

void GolfMatch::settle_official(int slot, const GolfTick& t) {
  Athlete& a = athletes_[slot];
  const GolfCall call = a.hole_ref.step(t);
  auto event = [&](const char* name) {
    nlohmann::json e = referee_event(name, time(), slot);
    e["stroke"] = a.hole_ref.strokes() + a.hole_ref.penalties();
    return e;
  };
  switch (call) {
    case GolfCall::None:
      return;
    case GolfCall::Stroke:
      log(event("stroke"));
      return;
    case GolfCall::Holed: {
      nlohmann::json e = event("holed");
      e["strokes"] = a.hole_ref.strokes();
      e["score"] = a.hole_ref.score();
      log(std::move(e));
      a.over = true;
      return;
    }
    case GolfCall::PickedUp: {
      nlohmann::json e = event("picked_up");
      e["reason"] = a.hole_ref.picked_up_reason();
      e["score"] = a.hole_ref.score();
      log(std::move(e));
      a.over = true;
      return;
    }
    case GolfCall::AtRest: {
      nlohmann::json e = event("at_rest");
      e["distance"] = (a.ball->position() - a.target).head<2>().norm();
      log(std::move(e));
      a.lie = a.ball->position();
      break;
    }
    case GolfCall::OutOfBounds:
      log(event("out_of_bounds"));
      a.ball->set_state(a.lie, Eigen::Vector3d::Zero());  // stroke and distance
      break;
  }
  // The next stroke is addressed from the lie: placed there, or the athlete walks there.
  if (rules_.placed_at_address) reset_player(slot, address(a));
}

void GolfMatch::settle_paper(int slot, const GolfTick& t) {
  Athlete& a = athletes_[slot];
  const auto ending = a.seed_ref.step(t);
  if (!ending) return;
  nlohmann::json e = referee_event("shot_end", time(), slot);
  e["reason"] = ending->reason;
  e["hit"] = ending->hit;
  e["stop_distance"] = ending->stop_distance;
  e["success"] = ending->success();
  log(std::move(e));
  a.over = true;
}

void GolfMatch::settle_tick() {
  for (int slot = 0; slot < slot_count(); ++slot) {
    Athlete& a = athletes_[slot];
    std::array<float, 4> terms{0, 0, 0, 0};
    if (!a.over) {
      const GolfTick t = read_tick(slot);
      const bool contact = rules_.official ? a.hole_ref.struck() || t.club_touch
                                           : a.seed_ref.contact() || t.seed_contact;
      terms = golf_reward_terms({a.ball_prev, a.ball->position(), a.ball->velocity(),
                                 club_head(slot), a.target, contact});
      if (rules_.official)
        settle_official(slot, t);
      else
        settle_paper(slot, t);
    }
    a.touched = false;
    a.ball_prev = a.ball->position();
    set_reward(slot, terms);
    outcome_.scores[slot] =
        rules_.official ? static_cast<float>(a.hole_ref.score())
                        : static_cast<float>(a.seed_ref.ending() && a.seed_ref.ending()->stopped
                                                 ? a.seed_ref.ending()->stop_distance
                                                 : -1.0);
  }
  if (std::all_of(athletes_.begin(), athletes_.end(), [](const Athlete& a) { return a.over; }))
    finish(rules_.official ? "holes_complete" : "shots_complete");
}

std::vector<int> GolfMatch::places() const {
  // A key per athlete, lower first: the score (official; a hole not finished scores the
  // maximum), or the stop distance (paper; no stop ranks after every stop).
  std::vector<double> key;
  for (const Athlete& a : athletes_) {
    if (rules_.official) {
      key.push_back(a.over ? a.hole_ref.score() : rules_.max_strokes);
    } else {
      const auto& e = a.seed_ref.ending();
      key.push_back(e && e->stopped ? e->stop_distance : 1e9);
    }
  }
  std::vector<int> place(key.size(), 1);
  for (size_t i = 0; i < key.size(); ++i)
    for (size_t j = 0; j < key.size(); ++j)
      if (key[j] < key[i]) ++place[i];
  return place;
}

void GolfMatch::finish(const std::string& why) {
  athletics::end_competition(outcome_, places(), outcome_.scores, why);
}

void GolfMatch::on_time_limit() {
  SmplMatch::on_time_limit();
  outcome_.info["places"] = places();
}

void GolfMatch::extra_state(std::vector<double>& values) const {
  for (const Athlete& a : athletes_) core::append_body_state(a.ball->body(), values);
}

void GolfMatch::write_task_observation(int slot, const HeadingFrame& frame,
                                       ObservationWriter& out) const {
  const Athlete& a = athletes_[slot];
  out.begin("ball")
      .field("position")
      .put(frame.point(a.ball->position()))
      .field("velocity")
      .put(frame.vector(a.ball->velocity()));
  out.begin("club_head").field("position").put(frame.point(club_head(slot)));
  out.begin("target").field("position").put(frame.point(a.target));
  const double left = 1.0 - (time() - a.start) / (rules_.official ? rules_.hole_s : time_limit_s());
  out.begin("play")
      .field("strokes")
      .put(static_cast<double>(a.hole_ref.strokes() + a.hole_ref.penalties()))
      .field("contact")
      .put((rules_.official ? a.hole_ref.struck() : a.seed_ref.contact()) ? 1.0 : 0.0)
      .field("time_left")
      .put(std::clamp(left, 0.0, 1.0));
}

void GolfMatch::describe_scene(SceneBuilder& scene) const {
  const double reach = rules_.official ? rules_.distance + 6 : rules_.max_target + 2;
  scene.set_ground(reach + slot_count() * rules_.lane_spacing, reach + 4, "#4f8f3a");
  for (int slot = 0; slot < slot_count(); ++slot) {
    const Athlete& a = athletes_[slot];
    if (a.hole) {
      const double g = rules_.green_radius;
      scene.add_ground_rect(a.target.x() - g, a.target.x() + g, a.target.y() - g, a.target.y() + g,
                            "green");
      scene.add_segment(-1, "cylinder", a.target - Eigen::Vector3d(0, 0, rules_.hole_depth),
                        a.target, rules_.hole_radius, "hole", "#202020");
    } else {
      scene.add_line(a.target + Eigen::Vector3d(-0.5, 0, 0.003),
                     a.target + Eigen::Vector3d(0.5, 0, 0.003), "target");
    }
  }
  for (int slot = 0; slot < slot_count(); ++slot) {
    const int ball = scene.add_body("ball", slot, "ball");
    scene.add_sphere(ball, Eigen::Vector3d::Zero(), athletes_[slot].ball->spec().radius, "ball",
                     "#ffffff");
  }
}

void GolfMatch::extra_scene_poses(std::vector<float>& out) const {
  for (const Athlete& a : athletes_) append_pose(out, a.ball->position(), a.ball->orientation());
}

}  // namespace olympics::sports::golf
