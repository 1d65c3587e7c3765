// The plug-in interface every sport implements, and what a match of it reports each tick.
//
// A SportMatch owns its world and steps it one control tick at a time; it knows nothing of the
// network. The server feeds it one action per slot per tick and publishes what it observes.
// Most sports do not implement SportMatch directly but build on framework/smpl_match.h, which
// owns what every SMPL match shares (slots and teams, ticks and the time limit, falls, forfeits,
// the observation layout and the state hash).
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/humanoid_assets.h"

namespace olympics::sports {

struct MatchSettings {
  std::string mode;
  std::uint64_t seed = 0;
  double time_limit_s = 0;  // 0: the sport's default
  // The sport's own settings (net height, match format, ...); a sport refuses keys it does not
  // know with std::invalid_argument naming the ones it does.
  nlohmann::json options = nlohmann::json::object();
};

// What one tick produced.
struct TickOutcome {
  std::vector<float> reward;              // per slot: the weighted sum of its terms
  std::vector<std::vector<float>> terms;  // per slot, per reward term (names: reward_terms())
  std::vector<std::uint8_t> done;         // per slot: its episode has ended
  std::vector<std::uint8_t> truncated;    // per slot: ended by the time limit
  bool match_over = false;
  std::string reason;                              // why it is over ("time_limit", ...)
  int winner_team = -1;                            // -1: draw / no winner
  std::vector<float> scores;                       // per team
  nlohmann::json info = nlohmann::json::object();  // referee calls ("events"), score, ...

  // The match is over for `why`: every slot is done; `winner` is a team or -1.
  void end(const std::string& why, int winner);
};

// Who wins when `losing_team` forfeits: the other team of two; with more teams, or when nobody
// is to blame (-1), nobody.
int forfeit_winner(int team_count, int losing_team);

// One mode of a sport: the team of each slot ({0, 0, 1, 1} for 2v2). The protocol carries this
// mapping to clients and the league, so nobody parses a mode's name.
struct ModeSpec {
  std::string name;
  std::vector<int> slot_teams;
  std::string summary;
  int slot_count() const { return static_cast<int>(slot_teams.size()); }
  int team_count() const;
};

// A sport's modes.
class ModeTable {
 public:
  ModeTable(std::string sport, std::vector<ModeSpec> modes);
  // Throws std::invalid_argument naming the sport's modes when `mode` is not one of them.
  const ModeSpec& at(const std::string& mode) const;
  std::vector<std::string> names() const;
  const std::vector<ModeSpec>& all() const { return modes_; }

 private:
  std::string sport_;
  std::vector<ModeSpec> modes_;
};

// A named field inside a block: where it starts in the block and how many floats it holds.
struct LayoutField {
  std::string name;
  int offset;
  int size;
};

// A field as a sport declares it: its name and how many floats it holds, in block order.
struct FieldSize {
  std::string name;
  int size;
};

// One named block of an observation or action vector, for `describe` and for clients, which
// find what they need by name: the protocol carries each block's name and size, and its fields'
// names and sizes. Every observation block declares its fields, in order, tiling the block (the
// self observation's come from core/self_observation_layout.h, a sport's from where it declares
// its task blocks, with of()); the ObservationWriter writes each block field by field by this
// declaration, so what is written and what clients read cannot drift apart.
struct LayoutBlock {
  std::string name;
  int size;
  std::string units;
  std::string meaning;
  std::vector<LayoutField> fields = {};

  // A block made of `fields` in order; its size is theirs together.
  static LayoutBlock of(std::string name, std::string units, std::string meaning,
                        const std::vector<FieldSize>& fields);
  // The field called `name`; throws std::invalid_argument naming the block's fields.
  const LayoutField& field(const std::string& name) const;
};

// A reward term: reported by name to the client beside the weighted total, so a trainer can
// re-weight; `weight` is its default weight in the total.
struct RewardTerm {
  std::string name;
  double weight = 1.0;
  std::string meaning;
};

// A call the referee can make; every event in a tick's info["events"] names one
// (framework/referee_events.h has the one shape every event takes). `announced` calls are the
// decisions people follow (a point, a goal, a knock-down: olympics-agent --calls prints them);
// the rest come many a second (contacts, hits, punches) or are bookkeeping (falls).
struct RefereeCall {
  std::string name;
  std::string meaning;
  bool announced = false;
};
// For call lists: {"goal", "...", kAnnounced}.
inline constexpr bool kAnnounced = true;

// How every humanoid sport's observation starts (the self observation, block "self") and what
// its action is (one target per hinge), for the humanoid `kind`: sizes and fields come from its
// loaded model (SMPL: 24 bodies, 358 floats, 69 targets; SMPL-X: 52 bodies, 778, 153).
inline constexpr const char* kSelfBlock = "self";
LayoutBlock self_observation_block(core::HumanoidKind kind);
LayoutBlock joint_targets_block(core::HumanoidKind kind);

// Everything a mode of a sport declares about its vectors and calls; sizes derive from it.
struct Layout {
  std::vector<LayoutBlock> observation;
  std::vector<LayoutBlock> action;
  std::vector<RewardTerm> rewards;
  std::vector<RefereeCall> calls;
  int observation_size() const;
  int action_size() const;
  std::vector<std::string> reward_names() const;
};

// The layout of a humanoid sport's mode: the self observation then `task` blocks, the joint
// targets, its reward terms and its referee's calls.
Layout humanoid_layout(core::HumanoidKind kind, const std::vector<LayoutBlock>& task,
                       std::vector<RewardTerm> rewards, std::vector<RefereeCall> calls);
// The same for the SMPL humanoid, which most sports play.
Layout smpl_layout(const std::vector<LayoutBlock>& task, std::vector<RewardTerm> rewards,
                   std::vector<RefereeCall> calls);

// A sport's settings: each key with its default, what it means, and what values it takes, for
// `describe` and for refusing what would break a match.
struct SettingSpec {
  std::string key;
  nlohmann::json default_value;
  std::string meaning;
  std::optional<double> min, max;    // a number: its allowed range (an integer default: integers)
  std::vector<std::string> choices;  // a string: its allowed values
  // The rulebook's value, where it differs from the default (the seed's, "paper"): what the
  // `rules` preset "official" sets unless the request sets this key itself.
  std::optional<nlohmann::json> official;
  std::string allowed() const;  // "1..45", "\"torso\" or \"whole_body\"", ...

  static SettingSpec number(std::string key, nlohmann::json value, std::string meaning, double min,
                            double max);
  static SettingSpec choice(std::string key, std::string value, std::string meaning,
                            std::vector<std::string> choices);
  // This setting with the rulebook's value `value` (the preset "official" sets it).
  SettingSpec with_official(nlohmann::json value) &&;
  // The preset every sport has: "paper" (the default: the seed's values, as the SMPLOlympics
  // paper has them) or "official" (every setting with an official value takes it at once).
  static SettingSpec rules_preset();
};

// Returns `options` over the defaults; throws std::invalid_argument naming the setting and what
// it takes when a key is unknown, a value has another JSON type than its default, a number is
// out of range (or not whole where the default is) or a string is not one of the choices.
// With "rules": "official" the settings' official values replace their defaults; a key the
// request sets itself keeps the request's value.
nlohmann::json merge_settings(const std::string& sport, const std::vector<SettingSpec>& specs,
                              const nlohmann::json& options);

class SportMatch {
 public:
  virtual ~SportMatch() = default;
  virtual int slot_count() const = 0;
  virtual int team_count() const = 0;
  virtual int team_of(int slot) const = 0;
  virtual int obs_size() const = 0;
  virtual int action_size() const = 0;
  virtual const std::vector<std::string>& reward_terms() const = 0;
  // The mode's layout (the sizes above derive from it) and the time limit in force.
  virtual const Layout& layout() const = 0;
  virtual double time_limit_s() const = 0;
  // Seconds of match time per tick: the control rate the server announces (1 / control_dt()).
  virtual double control_dt() const = 0;
  int control_hz() const { return static_cast<int>(std::lround(1.0 / control_dt())); }

  // Observation of tick `tick()` for one slot (self observation, then the task's).
  virtual void observe(int slot, std::span<float> out) const = 0;
  // Applies one action per slot (validated by the caller: right size, finite) and advances one
  // control tick.
  virtual void step(const std::vector<std::span<const float>>& actions) = 0;
  // The outcome of the last step (before any step: zeros, nothing over).
  virtual const TickOutcome& outcome() const = 0;
  virtual int tick() const = 0;
  // Ends the match now for an outside reason (a forfeit): `losing_team` loses (-1: nobody, e.g.
  // a match cancelled before it began).
  virtual void forfeit(int losing_team, const std::string& reason) = 0;
  // Hash of the complete physical state, for replays that must reproduce bit for bit.
  virtual std::uint64_t state_hash() const = 0;
  // Scene data for viewers (framework/scene_view.h): the description once, then after any tick
  // the poses of its moving bodies, 7 floats each in the description's body order. A match with
  // nothing to draw returns null and no poses.
  virtual nlohmann::json scene_description() const { return nullptr; }
  virtual void scene_poses(std::vector<float>& out) const { out.clear(); }
};

class Sport {
 public:
  virtual ~Sport() = default;
  virtual std::string name() const = 0;
  virtual std::string summary() const = 0;
  virtual const ModeTable& modes() const = 0;
  virtual double default_time_limit_s() const = 0;
  // Throws std::invalid_argument naming the known modes when the mode is unknown, and naming the
  // setting when an option is unknown or out of range.
  virtual std::unique_ptr<SportMatch> create(const MatchSettings& settings) const = 0;
  virtual Layout layout(const std::string& mode) const = 0;
  virtual std::vector<SettingSpec> settings() const { return {}; }
};

}  // namespace olympics::sports
