// The plug-in interface every sport implements, and what a match of it reports each tick.
//
// A SportMatch owns its world and steps it one control tick at a time; it knows nothing of the
// network. The server feeds it one action per slot per tick and publishes what it observes.
#pragma once

#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

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
  std::vector<float> reward;              // per slot
  std::vector<std::vector<float>> terms;  // per slot, per reward term (names: reward_terms())
  std::vector<std::uint8_t> done;         // per slot: its episode has ended
  std::vector<std::uint8_t> truncated;    // per slot: ended by the time limit
  bool match_over = false;
  std::string reason;                              // why it is over ("time_limit", ...)
  int winner_team = -1;                            // -1: draw / no winner
  std::vector<float> scores;                       // per team
  nlohmann::json info = nlohmann::json::object();  // referee calls, events

  // The match is over for `why`: every slot is done; `winner` is a team or -1.
  void end(const std::string& why, int winner);
};

// Who wins when `losing_team` forfeits: the other team of two; with more teams, or when nobody
// is to blame (-1), nobody.
int forfeit_winner(int team_count, int losing_team);

// One named block of an observation or action vector, for `describe`.
struct LayoutBlock {
  std::string name;
  int size;
  std::string units;
  std::string meaning;
};

// How every SMPL sport's observation starts (the self observation) and what its action is.
inline constexpr int kSmplSelfObservation = 358;
LayoutBlock smpl_self_observation_block();
LayoutBlock smpl_action_block();

struct Layout {
  std::vector<LayoutBlock> observation;
  std::vector<LayoutBlock> action;
  std::vector<std::string> reward_terms;
  int observation_size() const;
  int action_size() const;
};

// A sport's settings: each key with its default and what it means, for `describe` and for
// refusing unknown keys.
struct SettingSpec {
  std::string key;
  nlohmann::json default_value;
  std::string meaning;
};

// Returns `options` over the defaults; throws std::invalid_argument naming the sport's settings
// when a key is unknown or a value has another JSON type than its default.
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
};

class Sport {
 public:
  virtual ~Sport() = default;
  virtual std::string name() const = 0;
  virtual std::string summary() const = 0;
  virtual std::vector<std::string> modes() const = 0;
  virtual double default_time_limit_s() const = 0;
  // Throws std::invalid_argument naming the known modes when the mode is unknown.
  virtual std::unique_ptr<SportMatch> create(const MatchSettings& settings) const = 0;
  virtual Layout layout(const std::string& mode) const = 0;
  virtual std::vector<SettingSpec> settings() const { return {}; }
};

}  // namespace olympics::sports
