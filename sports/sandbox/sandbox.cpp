#include "sandbox/sandbox.h"

#include <map>
#include <stdexcept>

#include "core/humanoid_assets.h"
#include "core/rotation.h"
#include "core/self_observation.h"
#include "core/state_hash.h"

namespace olympics::sports {
namespace {

constexpr int kSelfObs = kSmplSelfObservation;
constexpr int kPerOther = 7;

// Mode -> team of each slot.
const std::map<std::string, std::vector<int>>& mode_teams() {
  static const std::map<std::string, std::vector<int>> modes = {
      {"solo", {0}},       {"1v1", {0, 1}},        {"2v2", {0, 0, 1, 1}},
      {"ffa3", {0, 1, 2}}, {"ffa4", {0, 1, 2, 3}},
  };
  return modes;
}

const std::vector<int>& teams_or_throw(const std::string& mode) {
  auto it = mode_teams().find(mode);
  if (it != mode_teams().end()) return it->second;
  std::string known;
  for (const auto& [name, teams] : mode_teams()) known += (known.empty() ? "" : ", ") + name;
  throw std::invalid_argument("sandbox has no mode \"" + mode + "\"; modes: " + known);
}

const core::ModelSpec& smpl() {
  static const core::ModelSpec spec = core::load_humanoid(core::HumanoidKind::Smpl);
  return spec;
}

}  // namespace

std::vector<std::string> SandboxSport::modes() const {
  std::vector<std::string> names;
  for (const auto& [name, teams] : mode_teams()) names.push_back(name);
  return names;
}

std::unique_ptr<SportMatch> SandboxSport::create(const MatchSettings& settings) const {
  MatchSettings s = settings;
  if (s.time_limit_s <= 0) s.time_limit_s = default_time_limit_s();
  merge_settings(name(), {}, s.options);  // the sandbox has no settings: refuses any
  return std::make_unique<SandboxMatch>(teams_or_throw(s.mode), s);
}

Layout SandboxSport::layout(const std::string& mode) const {
  const int others = static_cast<int>(teams_or_throw(mode).size()) - 1;
  Layout l;
  l.observation = {
      smpl_self_observation_block(),
      {"time_remaining", 1, "fraction", "share of the time limit still to play"},
  };
  if (others > 0)
    l.observation.push_back({"others", kPerOther * others, "m, m/s, flag",
                             "per other slot in slot order: root position (3) and root velocity "
                             "(3) in this humanoid's heading frame, fallen (1)"});
  l.action = {smpl_action_block()};
  l.reward_terms = {"alive", "fall"};
  return l;
}

SandboxMatch::SandboxMatch(std::vector<int> slot_teams, const MatchSettings& settings)
    : teams_(std::move(slot_teams)),
      time_limit_ticks_(static_cast<int>(settings.time_limit_s * 30.0 + 0.5)) {
  for (int t : teams_) team_count_ = std::max(team_count_, t + 1);
  // Humanoids on a circle of 1 m, facing its centre; the seed turns the circle.
  std::mt19937_64 rng(settings.seed);
  const double phase = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng);
  const int n = slot_count();
  for (int i = 0; i < n; ++i) {
    double angle = phase + 2 * M_PI * i / n;
    Eigen::Vector3d pos =
        n == 1 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0);
    scene_.add_humanoid(smpl(), {pos, angle + M_PI});
    falls_.emplace_back(smpl());
  }
  fallen_.assign(n, 0);
  outcome_.reward.assign(n, 0.0f);
  outcome_.terms.assign(n, std::vector<float>(terms_.size(), 0.0f));
  outcome_.done.assign(n, 0);
  outcome_.truncated.assign(n, 0);
  outcome_.scores.assign(team_count_, 0.0f);
}

int SandboxMatch::obs_size() const { return kSelfObs + 1 + kPerOther * (slot_count() - 1); }

void SandboxMatch::observe(int slot, std::span<float> out) const {
  const core::Humanoid& me = scene_.humanoid(slot);
  auto bodies = me.body_states();
  core::write_self_observation(bodies, out.subspan(0, kSelfObs));
  size_t k = kSelfObs;
  out[k++] = 1.0f - static_cast<float>(tick_) / static_cast<float>(time_limit_ticks_);
  const core::BodyState& root = bodies[0];
  const Eigen::Quaterniond heading_inv = core::inverse_heading(root.orientation);
  for (int other = 0; other < slot_count(); ++other) {
    if (other == slot) continue;
    core::BodyState o = scene_.humanoid(other).body_state(0);
    Eigen::Vector3d p = heading_inv * (o.position - root.position);
    Eigen::Vector3d v = heading_inv * o.linear_velocity;
    for (double x : {p.x(), p.y(), p.z(), v.x(), v.y(), v.z()})
      out[k++] =
          std::clamp(static_cast<float>(x), -core::kObservationClamp, core::kObservationClamp);
    out[k++] = fallen_[other] ? 1.0f : 0.0f;
  }
}

void SandboxMatch::step(const std::vector<std::span<const float>>& actions) {
  if (outcome_.match_over) return;
  for (int i = 0; i < slot_count(); ++i) scene_.set_action(i, actions[i]);
  scene_.tick();
  ++tick_;
  outcome_.info = nlohmann::json::object();
  for (int i = 0; i < slot_count(); ++i) {
    auto& terms = outcome_.terms[i];
    terms.assign(terms_.size(), 0.0f);
    if (!fallen_[i] && falls_[i].fallen(scene_.humanoid(i))) {
      fallen_[i] = 1;
      outcome_.done[i] = 1;
      terms[1] = -1.0f;
      outcome_.info["events"].push_back(
          {{"tick", tick_}, {"slot", i}, {"event", "fall"}, {"body", falls_[i].culprit()}});
    }
    if (!fallen_[i]) {
      terms[0] = 1.0f;
      outcome_.scores[teams_[i]] += 1.0f / 30.0f;
    }
    outcome_.reward[i] = terms[0] + terms[1];
  }
  decide_end();
}

void SandboxMatch::decide_end() {
  std::vector<bool> team_standing(team_count_, false);
  int standing = 0;
  for (int i = 0; i < slot_count(); ++i)
    if (!fallen_[i]) team_standing[teams_[i]] = true, ++standing;
  int teams_standing =
      static_cast<int>(std::count(team_standing.begin(), team_standing.end(), true));
  std::string reason;
  if (tick_ >= time_limit_ticks_)
    reason = "time_limit";
  else if (standing == 0)
    reason = "all_fell";
  else if (team_count_ > 1 && teams_standing == 1)
    reason = "last_team_standing";
  else
    return;
  // Winner: most points; a tie for the most is a draw. Points are exact multiples of 1/30 s
  // accumulated in the same order, so equal standing times compare equal.
  auto best = std::max_element(outcome_.scores.begin(), outcome_.scores.end());
  bool tie = std::count(outcome_.scores.begin(), outcome_.scores.end(), *best) > 1;
  outcome_.end(reason,
               (team_count_ > 1 && !tie) ? static_cast<int>(best - outcome_.scores.begin()) : -1);
  if (reason == "time_limit")
    for (int i = 0; i < slot_count(); ++i)
      if (!fallen_[i]) outcome_.truncated[i] = 1;
}

void SandboxMatch::forfeit(int losing_team, const std::string& reason) {
  if (outcome_.match_over) return;
  outcome_.end(reason, forfeit_winner(team_count_, losing_team));
}

std::uint64_t SandboxMatch::state_hash() const { return core::state_hash(scene_); }

}  // namespace olympics::sports
