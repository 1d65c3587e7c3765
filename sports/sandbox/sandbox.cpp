#include "sandbox/sandbox.h"

#include <algorithm>
#include <random>
#include <string>
#include <utility>

#include "core/humanoid_assets.h"
#include "core/self_observation.h"

namespace olympics::sports {
namespace {

// What the block "others" holds of each other slot: root position, root velocity, fallen.
constexpr std::pair<const char*, int> kOtherFields[] = {
    {"position", 3}, {"velocity", 3}, {"fallen", 1}};
// The field `what` of the k-th other slot ("position_0", ...).
std::string other_field(const char* what, int k) {
  std::string name = what;
  name += '_';
  name += std::to_string(k);
  return name;
}

const core::ModelSpec& smpl() {
  static const core::ModelSpec spec = core::load_humanoid(core::HumanoidKind::Smpl);
  return spec;
}

}  // namespace

SandboxSport::SandboxSport()
    : modes_("sandbox", {{"solo", {0}, "one humanoid"},
                         {"1v1", {0, 1}, "two humanoids, one a side"},
                         {"2v2", {0, 0, 1, 1}, "two teams of two"},
                         {"ffa3", {0, 1, 2}, "three humanoids, each for itself"},
                         {"ffa4", {0, 1, 2, 3}, "four humanoids, each for itself"}}) {}

std::unique_ptr<SportMatch> SandboxSport::create(const MatchSettings& settings) const {
  MatchSettings s = settings;
  if (s.time_limit_s <= 0) s.time_limit_s = default_time_limit_s();
  merge_settings(name(), {}, s.options);  // the sandbox has no settings: refuses any
  return std::make_unique<SandboxMatch>(modes_.at(s.mode), layout(s.mode), s);
}

Layout SandboxSport::layout(const std::string& mode) const {
  const int others = modes_.at(mode).slot_count() - 1;
  std::vector<LayoutBlock> task = {LayoutBlock::of(
      "time_remaining", "fraction", "share of the time limit still to play", {{"fraction", 1}})};
  std::vector<FieldSize> per_other;
  for (int k = 0; k < others; ++k)
    for (const auto& [field, size] : kOtherFields)
      per_other.push_back({other_field(field, k), size});
  if (others > 0)
    task.push_back(LayoutBlock::of("others", "m, m/s, flag",
                                   "per other slot in slot order: root position (3) and root "
                                   "velocity (3) in this humanoid's heading frame, clamped to "
                                   "+-5; fallen (1)",
                                   per_other));
  return smpl_layout(task,
                     {{"alive", 1.0, "+1 each tick while standing"},
                      {"fall", 1.0, "-1 on the tick the humanoid falls"}},
                     {{"fall",
                       "a humanoid fell (the body that touched the ground or dropped "
                       "too low)"}});
}

SandboxMatch::SandboxMatch(const ModeSpec& mode, Layout layout, const MatchSettings& settings)
    : SmplMatch(mode, std::move(layout), settings) {
  // Humanoids on a circle of 1 m, facing its centre; the seed turns the circle.
  const double phase = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng());
  const int n = slot_count();
  for (int i = 0; i < n; ++i) {
    const double angle = phase + 2 * M_PI * i / n;
    const Eigen::Vector3d pos =
        n == 1 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0);
    add_player(smpl(), {pos, angle + M_PI});
  }
  fallen_.assign(n, 0);
}

void SandboxMatch::write_task_observation(int slot, const HeadingFrame& frame,
                                          ObservationWriter& out) const {
  out.begin("time_remaining")
      .field("fraction")
      .put(1.0f - static_cast<float>(tick()) / static_cast<float>(time_limit_ticks()));
  if (slot_count() == 1) return;
  out.begin("others");
  int k = 0;
  for (int other = 0; other < slot_count(); ++other) {
    if (other == slot) continue;
    const core::BodyState o = player(other).body_state(0);
    out.field(other_field("position", k))
        .put_clamped(frame.point(o.position), core::kObservationClamp)
        .field(other_field("velocity", k))
        .put_clamped(frame.vector(o.linear_velocity), core::kObservationClamp)
        .field(other_field("fallen", k))
        .put(fallen_[other] ? 1.0 : 0.0);
    ++k;
  }
}

void SandboxMatch::settle_tick() {
  const float point_per_tick = static_cast<float>(scene().settings().control_dt);
  for (int i = 0; i < slot_count(); ++i) {
    float terms[2] = {0.0f, 0.0f};
    if (!fallen_[i] && down(i)) {
      fallen_[i] = 1;
      outcome_.done[i] = 1;
      terms[1] = -1.0f;
    }
    if (!fallen_[i]) {
      terms[0] = 1.0f;
      outcome_.scores[teams()[i]] += point_per_tick;
    }
    set_reward(i, terms);
  }
  std::vector<bool> team_standing(team_count(), false);
  int standing = 0;
  for (int i = 0; i < slot_count(); ++i)
    if (!fallen_[i]) team_standing[teams()[i]] = true, ++standing;
  const auto teams_standing = std::count(team_standing.begin(), team_standing.end(), true);
  // Winner: most points; a tie for the most is a draw. Points are exact multiples of the tick
  // accumulated in the same order, so equal standing times compare equal.
  if (time_up())
    end_by_time_limit(leading_team());
  else if (standing == 0)
    outcome_.end("all_fell", leading_team());
  else if (team_count() > 1 && teams_standing == 1)
    outcome_.end("last_team_standing", leading_team());
}

}  // namespace olympics::sports

namespace olympics::sports {
std::unique_ptr<Sport> make_sandbox() { return std::make_unique<SandboxSport>(); }
}  // namespace olympics::sports
