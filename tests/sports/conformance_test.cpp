// Every registered sport in every mode keeps the framework's promises. A new sport is covered by
// registering it: sizes match `describe`, values are finite, the same seed and actions give the
// same state hash, forfeits and the time limit end the match, unknown settings are refused, and
// every referee event has the one shape (framework/referee_events.h).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "framework/referee_events.h"
#include "registry.h"

namespace olympics::sports {
namespace {

struct SportMode {
  std::string sport, mode;
};
void PrintTo(const SportMode& m, std::ostream* os) { *os << m.sport << " " << m.mode; }

std::vector<SportMode> every_sport_and_mode() {
  std::vector<SportMode> all;
  for (const auto& name : sport_names())
    for (const auto& mode : sport_or_throw(name).modes().names()) all.push_back({name, mode});
  return all;
}

class Conformance : public ::testing::TestWithParam<SportMode> {
 protected:
  const Sport& sport() const { return sport_or_throw(GetParam().sport); }
  std::unique_ptr<SportMatch> make(std::uint64_t seed, double time_limit_s,
                                   const nlohmann::json& options = nlohmann::json::object()) const {
    return sport().create({GetParam().mode, seed, time_limit_s, options});
  }
};

// Random actions, the same for the same seed.
struct Actions {
  explicit Actions(const SportMatch& m, std::uint64_t seed)
      : rng(seed), values(m.slot_count(), std::vector<float>(m.action_size())) {}
  std::vector<std::span<const float>> next() {
    std::uniform_real_distribution<float> u(-1, 1);
    std::vector<std::span<const float>> spans;
    for (auto& v : values) {
      for (auto& x : v) x = u(rng);
      spans.emplace_back(v);
    }
    return spans;
  }
  std::mt19937_64 rng;
  std::vector<std::vector<float>> values;
};

TEST_P(Conformance, SizesAndTeamsMatchTheLayoutThatDescribeShows) {
  const Layout layout = sport().layout(GetParam().mode);
  const ModeSpec& mode = sport().modes().at(GetParam().mode);
  auto m = make(1, 2.0);
  EXPECT_EQ(m->obs_size(), layout.observation_size());
  EXPECT_EQ(m->action_size(), layout.action_size());
  EXPECT_EQ(m->reward_terms(), layout.reward_names());
  EXPECT_EQ(m->layout().observation.size(), layout.observation.size());
  ASSERT_FALSE(layout.observation.empty());
  EXPECT_EQ(layout.observation.front().name, "self");
  EXPECT_FALSE(layout.calls.empty()) << "every sport's referee calls at least a fall";
  EXPECT_EQ(m->slot_count(), mode.slot_count());
  EXPECT_EQ(m->team_count(), mode.team_count());
  for (int s = 0; s < m->slot_count(); ++s) EXPECT_EQ(m->team_of(s), mode.slot_teams[s]);
  std::set<std::string> names;
  for (const auto& b : layout.observation) EXPECT_TRUE(names.insert(b.name).second) << b.name;
  for (const auto& r : layout.rewards) EXPECT_TRUE(std::isfinite(r.weight)) << r.name;
  EXPECT_DOUBLE_EQ(m->time_limit_s(), 2.0);
  EXPECT_GT(make(1, 0.0)->time_limit_s(), 0.0) << "0 asks for the sport's default";
}

// Observations, rewards, terms and scores stay finite, and every event has the one shape.
TEST_P(Conformance, RandomPlayIsFiniteAndEveryEventFollowsTheSchema) {
  auto m = make(7, 4.0);
  const Layout& layout = m->layout();
  Actions actions(*m, 11);
  std::vector<float> obs(m->obs_size());
  int events = 0;
  while (!m->outcome().match_over) {
    for (int s = 0; s < m->slot_count(); ++s) {
      m->observe(s, obs);
      for (size_t k = 0; k < obs.size(); ++k)
        ASSERT_TRUE(std::isfinite(obs[k]))
            << "slot " << s << " obs[" << k << "] tick " << m->tick();
    }
    m->step(actions.next());
    const TickOutcome& o = m->outcome();
    ASSERT_EQ(o.reward.size(), static_cast<size_t>(m->slot_count()));
    ASSERT_EQ(o.scores.size(), static_cast<size_t>(m->team_count()));
    for (int s = 0; s < m->slot_count(); ++s) {
      ASSERT_TRUE(std::isfinite(o.reward[s]));
      ASSERT_EQ(o.terms[s].size(), layout.rewards.size());
      float weighted = 0;
      for (size_t k = 0; k < o.terms[s].size(); ++k) {
        ASSERT_TRUE(std::isfinite(o.terms[s][k]));
        weighted += static_cast<float>(layout.rewards[k].weight) * o.terms[s][k];
      }
      EXPECT_NEAR(o.reward[s], weighted, 1e-5) << "the reward is the weighted sum of its terms";
    }
    for (float x : o.scores) ASSERT_TRUE(std::isfinite(x));
    ASSERT_TRUE(o.info.contains("events")) << o.info.dump();
    for (const auto& e : o.info["events"]) {
      ++events;
      const auto problem =
          check_referee_event(e, layout, m->slot_count(), m->team_count(), m->tick());
      ASSERT_FALSE(problem) << *problem;
    }
  }
  EXPECT_LE(m->tick(), 4 * 30);
  std::printf("%s %s: %d ticks, %d referee events, %s\n", GetParam().sport.c_str(),
              GetParam().mode.c_str(), m->tick(), events, m->outcome().reason.c_str());
}

TEST_P(Conformance, SameSeedAndActionsGiveTheSameStateHash) {
  auto a = make(5, 3.0), b = make(5, 3.0);
  Actions xa(*a, 3), xb(*b, 3);
  EXPECT_EQ(a->state_hash(), b->state_hash());
  while (!a->outcome().match_over) {
    a->step(xa.next());
    b->step(xb.next());
    ASSERT_EQ(a->state_hash(), b->state_hash()) << "tick " << a->tick();
    ASSERT_EQ(a->outcome().reward, b->outcome().reward) << "tick " << a->tick();
  }
  EXPECT_TRUE(b->outcome().match_over);
  EXPECT_EQ(a->outcome().reason, b->outcome().reason);
  EXPECT_EQ(a->outcome().scores, b->outcome().scores);
  EXPECT_EQ(a->outcome().info.dump(), b->outcome().info.dump());
}

TEST_P(Conformance, TheTimeLimitEndsTheMatch) {
  auto m = make(2, 1.0);
  std::vector<float> zero(m->action_size(), 0.0f);
  const std::vector<std::span<const float>> actions(m->slot_count(), zero);
  while (!m->outcome().match_over && m->tick() < 1000) m->step(actions);
  ASSERT_TRUE(m->outcome().match_over);
  EXPECT_LE(m->tick(), 30);
  if (m->outcome().reason == "time_limit") {
    EXPECT_EQ(m->tick(), 30);
    bool any_truncated = false;
    for (auto t : m->outcome().truncated) any_truncated = any_truncated || t;
    EXPECT_TRUE(any_truncated) << "a match cut by the clock truncates its players";
  }
  for (auto d : m->outcome().done) EXPECT_TRUE(d);
}

TEST_P(Conformance, AForfeitEndsTheMatchForTheOtherTeam) {
  auto m = make(3, 10.0);
  Actions actions(*m, 1);
  for (int t = 0; t < 5 && !m->outcome().match_over; ++t) m->step(actions.next());
  // A match these actions end within 5 ticks (a javelin let go at once) forfeits before its first
  // step instead, so every sport and mode is checked.
  if (m->outcome().match_over) m = make(3, 10.0);
  m->forfeit(0, "forfeit: test");
  EXPECT_TRUE(m->outcome().match_over);
  EXPECT_EQ(m->outcome().reason, "forfeit: test");
  EXPECT_EQ(m->outcome().winner_team, forfeit_winner(m->team_count(), 0));
  for (auto d : m->outcome().done) EXPECT_TRUE(d);
  const int tick = m->tick();
  m->step(actions.next());
  EXPECT_EQ(m->tick(), tick) << "a finished match does not step";
}

TEST_P(Conformance, UnknownSettingsAndModesAreRefusedByName) {
  try {
    make(1, 2.0, {{"no_such_setting", 1}});
    ADD_FAILURE() << "an unknown setting was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_setting"), std::string::npos) << e.what();
  }
  for (const auto& s : sport().settings()) {
    const nlohmann::json wrong =
        s.default_value.is_string() ? nlohmann::json(12.5) : nlohmann::json("twelve");
    EXPECT_THROW(make(1, 2.0, {{s.key, wrong}}), std::invalid_argument) << s.key;
  }
  for (const auto& s : sport().settings()) {  // outside the range or the choices it declares
    if (s.min) {
      EXPECT_THROW(make(1, 2.0, {{s.key, *s.min - 1}}), std::invalid_argument) << s.key;
    }
    if (s.max) {
      EXPECT_THROW(make(1, 2.0, {{s.key, *s.max + 1}}), std::invalid_argument) << s.key;
    }
    if (!s.choices.empty()) {
      EXPECT_THROW(make(1, 2.0, {{s.key, "no_such_choice"}}), std::invalid_argument) << s.key;
    }
    if (s.default_value.is_number_integer()) {
      EXPECT_THROW(make(1, 2.0, {{s.key, s.default_value.get<double>() + 0.5}}),
                   std::invalid_argument)
          << s.key << " takes whole numbers";
    }
    if (s.default_value.is_number()) {
      EXPECT_TRUE(s.min && s.max) << s.key << ": a number setting declares its range";
    }
  }
  nlohmann::json defaults = nlohmann::json::object();
  for (const auto& s : sport().settings()) defaults[s.key] = s.default_value;
  EXPECT_NO_THROW(make(1, 2.0, defaults)) << "every default is a valid setting";
  try {
    sport().create({"no_such_mode", 1, 2.0, {}});
    ADD_FAILURE() << "an unknown mode was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(GetParam().mode), std::string::npos)
        << "the message lists the modes: " << e.what();
  }
}

// Viewers draw every sport from the same scene data (framework/scene_view.h): each slot's
// humanoid, shapes on bodies that exist, one pose per body each tick, and the poses follow the
// simulation (the players' roots are where their observation says they are).
TEST_P(Conformance, TheSceneDescribesEveryBodyAndItsPosesFollowPlay) {
  auto m = make(5, 2.0);
  const nlohmann::json scene = m->scene_description();
  ASSERT_TRUE(scene.is_object());
  const auto& bodies = scene.at("bodies");
  std::vector<int> per_slot(m->slot_count(), 0);
  for (const auto& b : bodies) {
    const int slot = b.at("slot");
    ASSERT_LT(slot, m->slot_count());
    if (slot >= 0) ++per_slot[slot];
  }
  for (int n : per_slot) EXPECT_GE(n, 24) << "every SMPL body of every slot";
  for (const auto& shape : scene.at("shapes")) {
    EXPECT_GE(shape.at("body").get<int>(), -1);
    EXPECT_LT(shape.at("body").get<int>(), static_cast<int>(bodies.size()));
    EXPECT_EQ(shape.at("size").size(), 3u);
    EXPECT_EQ(shape.at("quat").size(), 4u);
  }
  EXPECT_EQ(scene.at("teams").size(), static_cast<size_t>(m->slot_count()));
  std::vector<float> before, after;
  m->scene_poses(before);
  ASSERT_EQ(before.size(), 7 * bodies.size());
  Actions actions(*m, 3);
  for (int t = 0; t < 20 && !m->outcome().match_over; ++t) m->step(actions.next());
  m->scene_poses(after);
  ASSERT_EQ(after.size(), before.size());
  EXPECT_NE(after, before) << "bodies moved under random actions";
  for (float v : after) ASSERT_TRUE(std::isfinite(v));
  // Slot 0's root pose is its first body; its height is the self observation's first entry.
  std::vector<float> obs(m->obs_size());
  m->observe(0, obs);
  EXPECT_NEAR(after[2], obs[0], 1e-4);
}

INSTANTIATE_TEST_SUITE_P(EveryRegisteredSport, Conformance,
                         ::testing::ValuesIn(every_sport_and_mode()),
                         [](const ::testing::TestParamInfo<SportMode>& info) {
                           return info.param.sport + "_" + info.param.mode;
                         });

}  // namespace
}  // namespace olympics::sports
