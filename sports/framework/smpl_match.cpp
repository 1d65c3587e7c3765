#include "framework/smpl_match.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/self_observation.h"
#include "core/state_hash.h"

namespace olympics::sports {

SmplMatch::SmplMatch(const ModeSpec& mode, Layout layout, const MatchSettings& settings,
                     const core::SceneSettings& scene)
    : mode_(mode),
      layout_(std::move(layout)),
      reward_names_(layout_.reward_names()),
      scene_(scene),
      rng_(settings.seed),
      time_limit_ticks_(static_cast<int>(std::lround(settings.time_limit_s / scene.control_dt))) {
  if (layout_.observation.empty() || layout_.observation.front().name != kSelfBlock)
    throw std::logic_error("an SMPL match's observation begins with the self block");
  for (const auto& r : layout_.rewards) reward_weights_.push_back(static_cast<float>(r.weight));
  const int n = mode_.slot_count();
  outcome_.reward.assign(n, 0.0f);
  outcome_.terms.assign(n, std::vector<float>(reward_names_.size(), 0.0f));
  outcome_.done.assign(n, 0);
  outcome_.truncated.assign(n, 0);
  outcome_.scores.assign(mode_.team_count(), 0.0f);
  down_.assign(n, 0);
  clear_ticks_.assign(n, 0);
  down_since_.assign(n, 0);
}

void SmplMatch::add_player(const core::ModelSpec& spec, const core::RootPlacement& placement,
                           const std::vector<std::string>& fall_exempt) {
  if (scene_.humanoid_count() >= slot_count())
    throw std::logic_error("more players than the mode has slots");
  scene_.add_humanoid(spec, placement);
  falls_.emplace_back(spec, fall_exempt);
}

int SmplMatch::slot_of_entity(int entity) const {
  for (int s = 0; s < slot_count(); ++s)
    if (player(s).entity() == entity) return s;
  return -1;
}

void SmplMatch::reset_player(int slot, const core::RootPlacement& placement) {
  scene_.humanoid(slot).reset(placement);
  falls_[slot].reset();
  down_[slot] = 0;
  clear_ticks_[slot] = 0;
}

SettingSpec SmplMatch::falls_setting(const std::string& default_choice) {
  return SettingSpec::choice("falls", default_choice,
                             "team play: a fallen player is only reported (its \"fallen\" term; "
                             "\"report\"), or stood up where it lies after 2 s, facing the way "
                             "its side plays (\"stand_up\")",
                             {"report", "stand_up"});
}

void SmplMatch::stand_up_fallen(const std::function<double(int)>& yaw) {
  for (int s = 0; s < slot_count(); ++s) {
    if (!down(s) || time_ - down_since_[s] < kStandUpAfterS) continue;
    const Eigen::Vector3d at = player(s).body_state(0).position;
    reset_player(s, {{at.x(), at.y(), 0}, yaw(s)});
    log(referee_event("stood_up", time_, s));
  }
}

void SmplMatch::observe(int slot, std::span<float> out) const {
  ObservationWriter writer(layout_.observation, out);
  const auto bodies = scene_.humanoid(slot).body_states();
  core::write_self_observation(bodies, writer.begin(kSelfBlock).whole_block());
  write_task_observation(slot, HeadingFrame(bodies[0]), writer);
  writer.finish();
}

void SmplMatch::step(const std::vector<std::span<const float>>& actions) {
  if (outcome_.match_over) return;
  if (scene_.humanoid_count() != slot_count())
    throw std::logic_error("a match stepped before every slot has its player");
  for (int i = 0; i < slot_count(); ++i) scene_.set_action(i, actions[i]);
  // The tick's log opens before its physics: calls are made at the physics rate.
  events_.begin_tick(tick_ + 1);
  outcome_.info = nlohmann::json::object();
  const double h = scene_.settings().physics_dt();
  for (int s = 0; s < scene_.settings().substeps; ++s) {
    before_physics_step();
    scene_.physics_step();
    const double step_start = time_;
    time_ += h;
    after_physics_step(step_start);
  }
  ++tick_;

  fell_.clear();
  const int up_after = static_cast<int>(std::lround(kUpAfterS / scene_.settings().control_dt));
  for (int i = 0; i < slot_count(); ++i) {
    const bool was_down = down_[i] != 0;
    if (falls_[i].fallen(scene_.humanoid(i))) {
      down_[i] = 1;
      clear_ticks_[i] = 0;
    } else if (was_down && ++clear_ticks_[i] >= up_after) {
      down_[i] = 0;
    }
    if (down_[i] && !was_down) {
      fell_.push_back(i);
      down_since_[i] = time_;
      nlohmann::json e = referee_event("fall", time_, i);
      e["body"] = falls_[i].culprit();
      log(std::move(e));
    }
  }
  settle_tick();
  if (!outcome_.match_over && time_up()) on_time_limit();
  outcome_.info["events"] = events_.events();
}

void SmplMatch::set_reward(int slot, std::span<const float> terms) {
  if (terms.size() != reward_weights_.size())
    throw std::logic_error("reward terms: " + std::to_string(terms.size()) + " for a layout of " +
                           std::to_string(reward_weights_.size()));
  outcome_.terms[slot].assign(terms.begin(), terms.end());
  float total = 0.0f;
  for (size_t k = 0; k < terms.size(); ++k) total += reward_weights_[k] * terms[k];
  outcome_.reward[slot] = total;
}

int SmplMatch::leading_team() const {
  if (team_count() < 2) return -1;
  const auto& s = outcome_.scores;
  const auto best = std::max_element(s.begin(), s.end());
  return std::count(s.begin(), s.end(), *best) > 1 ? -1 : static_cast<int>(best - s.begin());
}

void SmplMatch::end_by_time_limit(int winner_team) {
  for (int i = 0; i < slot_count(); ++i)
    if (!outcome_.done[i]) outcome_.truncated[i] = 1;
  outcome_.end("time_limit", winner_team);
}

void SmplMatch::on_time_limit() { end_by_time_limit(leading_team()); }

void SmplMatch::forfeit(int losing_team, const std::string& reason) {
  if (outcome_.match_over) return;
  outcome_.end(reason, forfeit_winner(team_count(), losing_team));
}

std::uint64_t SmplMatch::state_hash() const {
  std::vector<double> extra;
  extra_state(extra);
  return core::state_hash(scene_, extra);
}

nlohmann::json SmplMatch::scene_description() const {
  SceneBuilder scene;
  for (int s = 0; s < slot_count(); ++s) {
    const core::ModelSpec& spec = player(s).spec();
    for (const auto& body : spec.bodies) {
      const int b = scene.add_body("slot" + std::to_string(s) + "/" + body.name, s, "player");
      for (const auto& g : body.geoms) scene.add_geom(b, g, g.held ? "equipment" : "player");
    }
  }
  describe_scene(scene);
  nlohmann::json out = scene.json();
  out["teams"] = mode_.slot_teams;
  return out;
}

void SmplMatch::scene_poses(std::vector<float>& out) const {
  out.clear();
  for (int s = 0; s < slot_count(); ++s)
    for (int b = 0; b < player(s).body_count(); ++b) {
      const core::BodyState st = player(s).body_state(b);
      append_pose(out, st.position, st.orientation);
    }
  extra_scene_poses(out);
}

}  // namespace olympics::sports
