#include "sport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/self_observation_layout.h"

namespace olympics::sports {

void TickOutcome::end(const std::string& why, int winner) {
  match_over = true;
  reason = why;
  winner_team = winner;
  for (auto& d : done) d = 1;
}

int forfeit_winner(int team_count, int losing_team) {
  return team_count == 2 && losing_team >= 0 ? 1 - losing_team : -1;
}

int ModeSpec::team_count() const {
  int teams = 0;
  for (int t : slot_teams) teams = std::max(teams, t + 1);
  return teams;
}

ModeTable::ModeTable(std::string sport, std::vector<ModeSpec> modes)
    : sport_(std::move(sport)), modes_(std::move(modes)) {}

const ModeSpec& ModeTable::at(const std::string& mode) const {
  for (const auto& m : modes_)
    if (m.name == mode) return m;
  std::string known;
  for (const auto& m : modes_) known += (known.empty() ? "" : ", ") + m.name;
  throw std::invalid_argument(sport_ + " has no mode \"" + mode + "\"; modes: " + known);
}

std::vector<std::string> ModeTable::names() const {
  std::vector<std::string> names;
  for (const auto& m : modes_) names.push_back(m.name);
  return names;
}

LayoutBlock LayoutBlock::of(std::string name, std::string units, std::string meaning,
                            const std::vector<FieldSize>& fields) {
  LayoutBlock block{std::move(name), 0, std::move(units), std::move(meaning)};
  for (const auto& f : fields) {
    if (f.size <= 0)
      throw std::logic_error("observation block \"" + block.name + "\": field \"" + f.name +
                             "\" declares no floats");
    block.fields.push_back({f.name, block.size, f.size});
    block.size += f.size;
  }
  return block;
}

const LayoutField& LayoutBlock::field(const std::string& field_name) const {
  for (const auto& f : fields)
    if (f.name == field_name) return f;
  std::string known;
  for (const auto& f : fields) known += (known.empty() ? "" : ", ") + f.name;
  throw std::invalid_argument("block \"" + name + "\" has no field \"" + field_name +
                              "\"; its fields: " + (known.empty() ? "none" : known));
}

namespace {

// Each humanoid's model, loaded once (it is read-only).
const core::ModelSpec& loaded_model(core::HumanoidKind kind) {
  if (kind == core::HumanoidKind::Smpl) {
    static const core::ModelSpec smpl = core::load_humanoid(core::HumanoidKind::Smpl);
    return smpl;
  }
  static const core::ModelSpec smplx = core::load_humanoid(core::HumanoidKind::SmplX);
  return smplx;
}

}  // namespace

LayoutBlock self_observation_block(core::HumanoidKind kind) {
  const int bodies = static_cast<int>(loaded_model(kind).bodies.size());
  const core::SelfObservationLayout at{bodies};
  const std::string b = std::to_string(bodies);
  LayoutBlock block{
      kSelfBlock, at.size(), "m, m/s, rad/s",
      "root height; " + std::to_string(bodies - 1) + " body positions rel. root; " + b +
          " tan-norm rotations; " + b + " linear and " + b +
          " angular velocities; heading frame, clamped to +-5" +
          (kind == core::HumanoidKind::SmplX ? " (HUMANOID-SMPLX.md body order)" : "")};
  for (const auto& f : at.fields()) block.fields.push_back({std::string(f.name), f.offset, f.size});
  return block;
}

LayoutBlock joint_targets_block(core::HumanoidKind kind) {
  const int hinges = loaded_model(kind).dof_count();
  const std::string joints =
      std::to_string(hinges / 3) + " joints x (x, y, z) hinges in body order, L_Hip first";
  if (kind == core::HumanoidKind::Smpl)
    return {"joint_targets", hinges, "a (target = pi*a rad; knee flexion 5*a)", joints};
  return {"joint_targets", hinges,
          "a (target = s*a rad, s = min(1.2 * the hinge's largest limit, pi); knee flexion 5*a)",
          joints + ", each hand's fingers after its wrist"};
}

Layout humanoid_layout(core::HumanoidKind kind, const std::vector<LayoutBlock>& task,
                       std::vector<RewardTerm> rewards, std::vector<RefereeCall> calls) {
  Layout l;
  l.observation = {self_observation_block(kind)};
  l.observation.insert(l.observation.end(), task.begin(), task.end());
  l.action = {joint_targets_block(kind)};
  l.rewards = std::move(rewards);
  l.calls = std::move(calls);
  return l;
}

Layout smpl_layout(const std::vector<LayoutBlock>& task, std::vector<RewardTerm> rewards,
                   std::vector<RefereeCall> calls) {
  return humanoid_layout(core::HumanoidKind::Smpl, task, std::move(rewards), std::move(calls));
}

int Layout::observation_size() const {
  int n = 0;
  for (const auto& b : observation) n += b.size;
  return n;
}

int Layout::action_size() const {
  int n = 0;
  for (const auto& b : action) n += b.size;
  return n;
}

std::vector<std::string> Layout::reward_names() const {
  std::vector<std::string> names;
  for (const auto& r : rewards) names.push_back(r.name);
  return names;
}

SettingSpec SettingSpec::number(std::string key, nlohmann::json value, std::string meaning,
                                double min, double max) {
  SettingSpec s;
  s.key = std::move(key), s.default_value = std::move(value), s.meaning = std::move(meaning);
  s.min = min, s.max = max;
  return s;
}

SettingSpec SettingSpec::choice(std::string key, std::string value, std::string meaning,
                                std::vector<std::string> choices) {
  SettingSpec s;
  s.key = std::move(key), s.default_value = std::move(value), s.meaning = std::move(meaning);
  s.choices = std::move(choices);
  return s;
}

SettingSpec SettingSpec::with_official(nlohmann::json value) && {
  official = std::move(value);
  return std::move(*this);
}

SettingSpec SettingSpec::rules_preset() {
  return choice("rules", "paper",
                "\"paper\": the seed's values (the defaults); \"official\": the rulebook's for "
                "every setting where they differ (a setting given beside it still wins)",
                {"paper", "official"});
}

std::string SettingSpec::allowed() const {
  if (!choices.empty()) {
    std::string text;
    for (size_t i = 0; i < choices.size(); ++i)
      text += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + ("\"" + choices[i] + "\"");
    return text;
  }
  auto number = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return std::string(text);
  };
  if (min && max) return number(*min) + ".." + number(*max);
  if (min) return ">= " + number(*min);
  if (max) return "<= " + number(*max);
  return default_value.type_name();
}

nlohmann::json merge_settings(const std::string& sport, const std::vector<SettingSpec>& specs,
                              const nlohmann::json& options) {
  nlohmann::json merged = nlohmann::json::object();
  std::string known;
  for (const auto& s : specs) {
    merged[s.key] = s.default_value;
    known += (known.empty() ? "" : ", ") + s.key;
  }
  if (known.empty()) known = "none";
  if (options.is_null()) return merged;  // no options given: the defaults
  if (!options.is_object()) throw std::invalid_argument(sport + ": settings must be a JSON object");
  for (const auto& [key, value] : options.items()) {
    const auto spec = std::find_if(specs.begin(), specs.end(),
                                   [&](const SettingSpec& s) { return s.key == key; });
    if (spec == specs.end())
      throw std::invalid_argument(sport + " has no setting \"" + key +
                                  "\"; its settings: " + known);
    const auto& def = spec->default_value;
    auto refuse = [&](const std::string& what) {
      throw std::invalid_argument(sport + " setting \"" + key + "\" must be " + what + ", got " +
                                  value.dump());
    };
    const bool both_numbers = def.is_number() && value.is_number();
    if (!both_numbers && def.type() != value.type())
      refuse(std::string("a ") + def.type_name() + " like " + def.dump());
    if (value.is_number()) {
      const double x = value.get<double>();
      if (!std::isfinite(x)) refuse("a finite number");
      if (def.is_number_integer() && x != std::floor(x)) refuse("a whole number");
      if ((spec->min && x < *spec->min) || (spec->max && x > *spec->max)) refuse(spec->allowed());
    }
    if (value.is_string() && !spec->choices.empty() &&
        std::find(spec->choices.begin(), spec->choices.end(), value.get<std::string>()) ==
            spec->choices.end())
      refuse(spec->allowed());
    merged[key] = value;
  }
  if (merged.contains("rules") && merged["rules"] == "official")
    for (const auto& s : specs)
      if (s.official && !options.contains(s.key)) merged[s.key] = *s.official;
  return merged;
}

}  // namespace olympics::sports
