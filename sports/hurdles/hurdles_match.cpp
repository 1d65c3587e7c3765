#include "hurdles/hurdles_match.h"

#include <algorithm>
#include <cmath>

#include "athletics/athlete_probe.h"
#include "athletics/competition.h"
#include "core/humanoid_assets.h"
#include "framework/jittered_start.h"
#include "hurdles/hurdles_rewards.h"
#include "hurdles/race_places.h"

namespace olympics::sports::hurdles {
namespace {

const core::ModelSpec& athlete_model() {
  static const core::ModelSpec spec = core::load_humanoid(core::HumanoidKind::Smpl);
  return spec;
}

// The humanoid's bodies whose names contain one of `parts`.
std::vector<int> bodies_named(const core::Humanoid& h, std::initializer_list<const char*> parts) {
  std::vector<int> found;
  for (int b = 0; b < h.body_count(); ++b)
    for (const char* p : parts)
      if (h.spec().bodies[b].name.find(p) != std::string::npos) {
        found.push_back(b);
        break;
      }
  return found;
}

}  // namespace

std::vector<LayoutBlock> hurdles_task_layout() {
  std::vector<FieldSize> hurdles;
  for (int i = 0; i < kHurdles; ++i) hurdles.push_back({"hurdle_" + std::to_string(i), 3});
  return {LayoutBlock::of("goal", "m",
                          "the seed's goal: the finish line's point on my lane's centre, 1 m up, "
                          "relative to the root, heading frame",
                          {{"position", 3}}),
          LayoutBlock::of("hurdles", "m",
                          "each hurdle's top bar centre (its top edge; where it is now, knocked "
                          "over or not) relative to the root, heading frame, first to last",
                          hurdles),
          LayoutBlock::of("race", "fraction, count, flag",
                          "share of the race's time left, hurdles I knocked over, my race is "
                          "decided (finished, did not finish or disqualified: 1/0)",
                          {{"time_left", 1}, {"knocked", 1}, {"decided", 1}})};
}

std::vector<RefereeCall> hurdles_calls() {
  return {
      {"finish", "an athlete finished: time (s), knocked (hurdles knocked over)", kAnnounced},
      {"disqualified", "an athlete was disqualified: reason (left_lane, trail_leg)", kAnnounced},
      {"did_not_finish",
       "an athlete's race ended without a finish: reason (fell, touched_hurdle, left_track, "
       "time)",
       kAnnounced},
      {"knocked", "a hurdle in the athlete's lane went over: hurdle (0 = the first)"},
      {"fall", "an athlete fell (body)"}};
}

HurdlesMatch::HurdlesMatch(const HurdlesRules& rules, const ModeSpec& mode, Layout layout,
                           const MatchSettings& settings)
    : SmplMatch(mode, std::move(layout), settings), rules_(rules) {
  for (int slot = 0; slot < slot_count(); ++slot) {
    build_lane(slot);
    // Seeds differ: the start mark moved by up to 0.1 m and turned by up to 0.1 rad.
    add_player(athlete_model(), jittered_start({rules_.start_x, lane_y(slot)}, 0.0, rng()));
  }
  torso_ = bodies_named(player(0), {"Pelvis", "Torso", "Spine", "Chest"});
  legs_ = bodies_named(player(0), {"Knee", "Ankle", "Toe"});
  feet_ = athletics::foot_bodies(player(0));
  for (int slot = 0; slot < slot_count(); ++slot) {
    Athlete a(rules_);
    a.root_prev = a.reward_root_prev = player(slot).body_state(0).position;
    athletes_.push_back(std::move(a));
    athletes_.back().torso_front_prev = torso_front_x(slot);
    athletes_.back().legs_prev = leg_positions(slot);
  }
}

void HurdlesMatch::build_lane(int slot) {
  Lane lane;
  // The lane's hurdles in one space inside the world's: the broad phase meets one entry per lane
  // (its athlete's geoms then test the lane's ten hurdles), not one per hurdle.
  const dSpaceID lane_space =
      rules_.free_hurdles ? dSimpleSpaceCreate(scene().world().space()) : nullptr;
  for (int i = 0; i < kHurdles; ++i) {
    const double x = rules_.hurdle_x(i);
    if (rules_.free_hurdles) {
      lane.hurdles.push_back(
          std::make_unique<Hurdle>(scene().world(), rules_, x, lane_y(slot), lane_space));
      lane.hurdles.back()->set_awake(false);  // until an athlete comes near
      lane.counted.push_back(false);
    } else {  // the seed's: a fixed box centred on the ground, its top at the hurdle's height
      dGeomID g = scene().world().add_static_box(
          {x, lane_y(slot), 0.0},
          {0.5 * rules_.wall_depth, 0.5 * rules_.wall_width, rules_.hurdle_height}, 1.0, 0.0);
      core::GeomTag& tag = core::PhysicsWorld::tag_of(g);
      tag.sensor = true;  // its contacts come with their forces
      lane.walls.push_back(&tag);
    }
  }
  lanes_.push_back(std::move(lane));
}

double HurdlesMatch::torso_front_x(int slot) const {
  const core::Humanoid& h = player(slot);
  double front = -1e9;
  for (int b : torso_)
    for (dGeomID g = dBodyGetFirstGeom(h.ode_body(b)); g; g = dBodyGetNextGeom(g)) {
      dReal aabb[6];
      dGeomGetAABB(g, aabb);
      front = std::max(front, static_cast<double>(aabb[1]));
    }
  return front;
}

std::vector<Eigen::Vector3d> HurdlesMatch::leg_positions(int slot) const {
  std::vector<Eigen::Vector3d> p;
  for (int b : legs_) p.push_back(player(slot).body_state(b).position);
  return p;
}

bool HurdlesMatch::touched_a_wall(int slot) const {
  const auto& walls = lanes_[slot].walls;
  const int entity = player(slot).entity();
  for (const auto& s : scene().world().sensed_contacts()) {
    if (!s.other || s.other->entity != entity || s.normal_force <= rules_.touch_force_n) continue;
    if (std::find(feet_.begin(), feet_.end(), s.other->body) != feet_.end()) continue;
    if (std::find(walls.begin(), walls.end(), s.sensor) != walls.end()) return true;
  }
  return false;
}

bool HurdlesMatch::trail_leg_beside(int slot, const std::vector<Eigen::Vector3d>& legs) const {
  const Lane& lane = lanes_[slot];
  const auto& prev = athletes_[slot].legs_prev;
  for (int i = 0; i < kHurdles; ++i) {
    if (rules_.free_hurdles && lane.hurdles[i]->knocked_over()) continue;  // no longer there
    const double x = rules_.hurdle_x(i);
    for (size_t k = 0; k < legs.size(); ++k) {
      const bool crossed = prev[k].x() < x && legs[k].x() >= x;
      const bool beside = std::abs(legs[k].y() - lane_y(slot)) > 0.5 * rules_.hurdle_width;
      if (crossed && beside && legs[k].z() < rules_.hurdle_height) return true;
    }
  }
  return false;
}

RaceStep HurdlesMatch::read_step(int slot, double step_start) {
  const core::Humanoid& h = player(slot);
  Athlete& a = athletes_[slot];
  RaceStep s;
  s.t = time();
  s.dt = time() - step_start;
  s.torso_front_x = torso_front_x(slot);
  s.torso_front_x_prev = a.torso_front_prev;
  const Eigen::Vector3d root = h.body_state(0).position;
  s.root_x = root.x();
  s.root_x_prev = a.root_prev.x();
  s.root_y = root.y() - lane_y(slot);
  // TR 17.3.1: stepping on or over the lane's lines (a foot; a hand that breaks a fall does not)
  for (const auto& g : scene().world().ground_contacts())
    if (g.geom->entity == h.entity() &&
        std::find(feet_.begin(), feet_.end(), g.geom->body) != feet_.end() &&
        std::abs(g.position.y() - lane_y(slot)) > 0.5 * rules_.lane_width)
      s.outside_lane = true;
  const auto legs = leg_positions(slot);
  s.trail_leg_beside = trail_leg_beside(slot, legs);
  s.hurdle_touch = !rules_.free_hurdles && touched_a_wall(slot);
  s.down = down(slot);
  a.torso_front_prev = s.torso_front_x;
  a.root_prev = root;
  a.legs_prev = legs;
  return s;
}

void HurdlesMatch::after_physics_step(double step_start) {
  for (int slot = 0; slot < slot_count(); ++slot) {
    Athlete& a = athletes_[slot];
    const RaceStep s = read_step(slot, step_start);
    if (a.result) continue;
    if (auto r = a.referee.step(s)) a.result = *r;
  }
}

void HurdlesMatch::count_knocked(int slot) {
  Lane& lane = lanes_[slot];
  for (int i = 0; i < static_cast<int>(lane.hurdles.size()); ++i) {
    if (lane.counted[i] || !lane.hurdles[i]->knocked_over()) continue;
    lane.counted[i] = true;
    ++athletes_[slot].knocked;
    nlohmann::json e = referee_event("knocked", time(), slot);
    e["hurdle"] = i;
    log(std::move(e));
  }
}

// A hurdle sleeps while it is at rest and no athlete's root is within reach of it: kWakeBehind_m
// before it to kWakeAhead_m past it along the track, and two lanes either side (an athlete moves
// at most a third of a metre a tick).
void HurdlesMatch::wake_hurdles_near_athletes() {
  constexpr double kWakeBehind_m = 3.0, kWakeAhead_m = 2.0, kWakeAcross_m = 2.5;
  std::vector<Eigen::Vector3d> roots;
  for (int slot = 0; slot < slot_count(); ++slot)
    roots.push_back(player(slot).body_state(0).position);
  for (int lane = 0; lane < slot_count(); ++lane)
    for (int i = 0; i < static_cast<int>(lanes_[lane].hurdles.size()); ++i) {
      Hurdle& h = *lanes_[lane].hurdles[i];
      const double x = rules_.hurdle_x(i), y = lane_y(lane);
      const bool near = std::any_of(roots.begin(), roots.end(), [&](const Eigen::Vector3d& r) {
        return r.x() > x - kWakeBehind_m && r.x() < x + kWakeAhead_m &&
               std::abs(r.y() - y) < kWakeAcross_m;
      });
      if (near)
        h.set_awake(true);
      else if (h.at_rest())
        h.set_awake(false);
    }
}

void HurdlesMatch::announce(int slot) {
  Athlete& a = athletes_[slot];
  const RaceResult& r = *a.result;
  const char* call = r.finished()                               ? "finish"
                     : r.kind == RaceResult::Kind::Disqualified ? "disqualified"
                                                                : "did_not_finish";
  nlohmann::json e = referee_event(call, time(), slot);
  if (r.finished()) {
    e["time"] = r.time;
    e["knocked"] = a.knocked;
  } else {
    e["reason"] = r.reason;
  }
  log(std::move(e));
  a.announced = true;
}

void HurdlesMatch::settle_tick() {
  if (rules_.free_hurdles) wake_hurdles_near_athletes();
  for (int slot = 0; slot < slot_count(); ++slot) {
    Athlete& a = athletes_[slot];
    if (rules_.free_hurdles) count_knocked(slot);
    if (a.result && !a.announced) announce(slot);
    const Eigen::Vector3d root = player(slot).body_state(0).position;
    set_reward(slot, hurdles_reward_terms(a.reward_root_prev, root, goal(slot)));
    a.reward_root_prev = root;
    outcome_.scores[slot] =
        a.result && a.result->finished() ? static_cast<float>(a.result->time) : 0.0f;
  }
  if (std::all_of(athletes_.begin(), athletes_.end(),
                  [](const Athlete& a) { return a.result.has_value(); }))
    finish("race_complete");
}

void HurdlesMatch::on_time_limit() {
  for (int slot = 0; slot < slot_count(); ++slot) {
    if (athletes_[slot].result) continue;
    athletes_[slot].result = RaceResult::dnf("time");
    announce(slot);
  }
  for (int i = 0; i < slot_count(); ++i)
    if (!outcome_.done[i]) outcome_.truncated[i] = 1;
  finish("time_limit");
}

void HurdlesMatch::finish(const std::string& why) {
  std::vector<std::optional<RaceResult>> results;
  std::vector<float> times;
  nlohmann::json knocked = nlohmann::json::array(), ends = nlohmann::json::array();
  for (const auto& a : athletes_) {
    results.push_back(a.result);
    times.push_back(a.result->finished() ? static_cast<float>(a.result->time) : 0.0f);
    knocked.push_back(a.knocked);
    ends.push_back(a.result->finished() ? "finished" : a.result->reason);
  }
  outcome_.info["knocked"] = knocked;
  outcome_.info["results"] = ends;
  athletics::end_competition(outcome_, race_places(results), times, why);
}

Eigen::Vector3d HurdlesMatch::hurdle_top(int slot, int i) const {
  if (rules_.free_hurdles) return lanes_[slot].hurdles[i]->top_centre();
  return {rules_.hurdle_x(i), lane_y(slot), rules_.hurdle_height};
}

void HurdlesMatch::write_task_observation(int slot, const HeadingFrame& frame,
                                          ObservationWriter& out) const {
  const Athlete& a = athletes_[slot];
  out.begin("goal").field("position").put(frame.point(goal(slot)));
  out.begin("hurdles");
  for (int i = 0; i < kHurdles; ++i)
    out.field("hurdle_" + std::to_string(i)).put(frame.point(hurdle_top(slot, i)));
  out.begin("race")
      .field("time_left")
      .put(std::clamp(1.0 - time() / time_limit_s(), 0.0, 1.0))
      .field("knocked")
      .put(static_cast<double>(a.knocked))
      .field("decided")
      .put(a.result ? 1.0 : 0.0);
}

void HurdlesMatch::extra_state(std::vector<double>& values) const {
  for (const auto& lane : lanes_)
    for (const auto& h : lane.hurdles) {
      const dBodyID b = h->body();
      for (const dReal* v : {dBodyGetPosition(b), dBodyGetLinearVel(b), dBodyGetAngularVel(b)})
        values.insert(values.end(), v, v + 3);
      const dReal* q = dBodyGetQuaternion(b);
      values.insert(values.end(), q, q + 4);
    }
}

void HurdlesMatch::describe_scene(SceneBuilder& scene) const {
  const double half_y = 0.5 * slot_count() * rules_.lane_spacing + 3;
  scene.set_ground(0.5 * rules_.race_m + 10, half_y, "#b5653c");
  for (int slot = 0; slot < slot_count(); ++slot) {
    const double y = lane_y(slot), w = 0.5 * rules_.lane_width;
    scene.add_ground_rect(0.0, rules_.race_m, y - w, y + w, "lane");
    scene.add_line({0.0, y - w, 0.003}, {0.0, y + w, 0.003}, "start_line");
    scene.add_line({rules_.race_m, y - w, 0.003}, {rules_.race_m, y + w, 0.003}, "finish_line");
    if (!rules_.free_hurdles)
      for (int i = 0; i < kHurdles; ++i)
        scene.add_box(
            -1, {rules_.hurdle_x(i), y, 0.5 * rules_.hurdle_height},
            {0.5 * rules_.wall_depth, 0.5 * rules_.wall_width, 0.5 * rules_.hurdle_height},
            "hurdle", "#8a8a8a");
  }
  for (int slot = 0; slot < slot_count(); ++slot)
    for (int i = 0; i < static_cast<int>(lanes_[slot].hurdles.size()); ++i) {
      const Hurdle& h = *lanes_[slot].hurdles[i];
      const int body =
          scene.add_body("hurdle_" + std::to_string(slot) + "_" + std::to_string(i), -1, "hurdle");
      for (const auto& p : h.parts())
        if (p.collides)
          scene.add_box(body, p.centre - h.centre_of_mass(), p.half, "hurdle", "#f2f2f2");
    }
}

void HurdlesMatch::extra_scene_poses(std::vector<float>& out) const {
  for (const auto& lane : lanes_)
    for (const auto& h : lane.hurdles) append_pose(out, h->position(), h->orientation());
}

}  // namespace olympics::sports::hurdles
