// The fields inside every observation block are declared once, where each sport declares its
// blocks: for every registered sport and mode they tile their blocks, the server writes each
// block field by field by that declaration (the ObservationWriter refuses anything else), and a
// client's by-name lookup (clients/cpp/observation_layout.h) finds there the values the sport
// wrote: the ball's position in the ball's position field, the opponent's chest in its chest
// field, another player's root in its position field.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "core/humanoid_assets.h"
#include "core/self_observation.h"
#include "framework/heading_frame.h"
#include "framework/observation_writer.h"
#include "observation_layout.h"
#include "registry.h"
#include "soccer/soccer_match.h"

namespace olympics::sports {
namespace {

// Plays `ticks` of random actions (seeded), so that every field holds something non-trivial.
void play(SportMatch& m, int ticks, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<std::vector<float>> actions(m.slot_count(), std::vector<float>(m.action_size()));
  for (int t = 0; t < ticks && !m.outcome().match_over; ++t) {
    std::vector<std::span<const float>> spans;
    for (auto& a : actions) {
      for (auto& x : a) x = std::uniform_real_distribution<float>(-0.3f, 0.3f)(rng);
      spans.emplace_back(a);
    }
    m.step(spans);
  }
}

Eigen::Vector3d read3(const std::vector<float>& o, int at) { return {o[at], o[at + 1], o[at + 2]}; }

TEST(TaskFields, EverySportsBlocksDeclareFieldsThatTileThemAndTheClientFindsThem) {
  int modes = 0;
  for (const auto& name : sport_names()) {
    const Sport& sport = sport_or_throw(name);
    for (const auto& mode : sport.modes().names()) {
      ++modes;
      SCOPED_TRACE(name + " " + mode);
      const Layout layout = sport.layout(mode);
      const auto client = client::ObservationLayout::from_blocks(layout.observation);
      int block_at = 0;
      for (const auto& b : layout.observation) {
        ASSERT_FALSE(b.fields.empty()) << "block " << b.name << " declares no fields";
        std::set<std::string> names;
        int at = 0;
        for (const auto& f : b.fields) {
          EXPECT_TRUE(names.insert(f.name).second) << b.name << "." << f.name << " twice";
          EXPECT_EQ(f.offset, at) << b.name << "." << f.name;
          EXPECT_GT(f.size, 0) << b.name << "." << f.name;
          EXPECT_EQ(client.offset(b.name, f.name), block_at + f.offset) << b.name << "." << f.name;
          EXPECT_EQ(client.size(b.name, f.name), f.size) << b.name << "." << f.name;
          at += f.size;
        }
        EXPECT_EQ(at, b.size) << "the fields of " << b.name << " add up to " << at;
        block_at += b.size;
      }
      EXPECT_EQ(client.total(), layout.observation_size());
      // The match writes every slot's observation by these fields (the writer throws on any
      // field out of order or of another size), before and during play.
      auto m = sport.create({mode, 3, 2.0, nlohmann::json::object()});
      std::vector<float> obs(m->obs_size());
      for (int tick = 0; tick < 2; ++tick) {
        for (int s = 0; s < m->slot_count(); ++s) EXPECT_NO_THROW(m->observe(s, obs)) << s;
        play(*m, 5, 1);
      }
    }
  }
  EXPECT_GE(modes, 15);
}

TEST(TaskFields, TheBallsPositionFieldIsTheBallsPosition) {
  auto m = sport_or_throw("soccer").create({"2v2", 4, 5.0, nlohmann::json::object()});
  play(*m, 20, 2);
  const auto& soccer = dynamic_cast<const soccer::SoccerMatch&>(*m);
  const auto layout = client::ObservationLayout::from_blocks(m->layout().observation);
  std::vector<float> obs(m->obs_size());
  for (int slot = 0; slot < m->slot_count(); ++slot) {
    m->observe(slot, obs);
    const HeadingFrame frame(soccer.scene().humanoid(slot).body_state(0));
    const Eigen::Vector3d ball = frame.point(soccer.ball().position());
    EXPECT_TRUE(read3(obs, layout.offset("ball", "position")).isApprox(ball, 1e-5)) << slot;
    // The first teammate's root: the other player of my side (slots 0, 1 and 2, 3).
    const int mate = slot ^ 1;
    const Eigen::Vector3d mate_root =
        frame.point(soccer.scene().humanoid(mate).body_state(0).position);
    EXPECT_TRUE(read3(obs, layout.offset("teammates", "position_0")).isApprox(mate_root, 1e-5));
    EXPECT_FLOAT_EQ(obs[layout.offset("match", "time_left")],
                    static_cast<float>(1.0 - 20.0 / (5.0 * 30)));
  }
}

TEST(TaskFields, TheOpponentsChestFieldIsItsChest) {
  auto m = sport_or_throw("boxing").create({"1v1", 6, 5.0, nlohmann::json::object()});
  play(*m, 15, 3);
  const auto& match = dynamic_cast<const SmplMatch&>(*m);
  const auto layout = client::ObservationLayout::from_blocks(m->layout().observation);
  const int chest_body = core::load_humanoid(core::HumanoidKind::Smpl).body_index("Chest");
  std::vector<float> obs(m->obs_size());
  m->observe(0, obs);
  const HeadingFrame frame(match.scene().humanoid(0).body_state(0));
  const Eigen::Vector3d chest =
      frame.point(match.scene().humanoid(1).body_state(chest_body).position);
  EXPECT_TRUE(read3(obs, layout.offset("opponent_targets", "chest")).isApprox(chest, 1e-5));
  EXPECT_EQ(layout.size("opponent_targets", "chest"), 3);
}

TEST(TaskFields, AnotherPlayersRootIsInItsPositionField) {
  auto m = sport_or_throw("sandbox").create({"ffa3", 8, 5.0, nlohmann::json::object()});
  play(*m, 10, 4);
  const auto& match = dynamic_cast<const SmplMatch&>(*m);
  const auto layout = client::ObservationLayout::from_blocks(m->layout().observation);
  std::vector<float> obs(m->obs_size());
  m->observe(1, obs);  // slot 1 sees slot 0 first, then slot 2
  const HeadingFrame frame(match.scene().humanoid(1).body_state(0));
  const Eigen::Vector3d second = frame.point(match.scene().humanoid(2).body_state(0).position);
  EXPECT_TRUE(
      read3(obs, layout.offset("others", "position_1"))
          .isApprox(second.cwiseMax(-core::kObservationClamp).cwiseMin(core::kObservationClamp),
                    1e-5));
  const float fallen = obs[layout.offset("others", "fallen_1")];
  EXPECT_TRUE(fallen == 0.0f || fallen == 1.0f) << fallen;
  EXPECT_EQ(layout.size("others", "fallen_1"), 1);
}

// The writer holds a sport to its declaration: fields in order, each of its declared size.
TEST(TaskFields, TheWriterRefusesAFieldOutOfOrderOrOfAnotherSize) {
  const std::vector<LayoutBlock> blocks = {
      LayoutBlock::of("goals", "m", "", {{"attack", 3}, {"defend", 3}})};
  std::vector<float> out(6);
  auto expect_refused = [](auto write, const std::string& naming) {
    try {
      write();
      ADD_FAILURE() << "accepted; expected a refusal naming " << naming;
    } catch (const std::logic_error& e) {
      EXPECT_NE(std::string(e.what()).find(naming), std::string::npos) << e.what();
    }
  };
  expect_refused([&] { ObservationWriter(blocks, out).begin("goals").field("defend"); },
                 "goals.defend");
  expect_refused([&] { ObservationWriter(blocks, out).begin("goals").put(1.0); }, "attack");
  expect_refused(
      [&] {
        ObservationWriter(blocks, out).begin("goals").field("attack").put(1.0).field("defend");
      },
      "goals.attack");
  expect_refused(
      [&] {
        ObservationWriter(blocks, out)
            .begin("goals")
            .field("attack")
            .put(Eigen::Vector3d(1, 2, 3))
            .put(4.0);
      },
      "goals.attack");
  ObservationWriter w(blocks, out);
  w.begin("goals")
      .field("attack")
      .put(Eigen::Vector3d(1, 2, 3))
      .field("defend")
      .put(Eigen::Vector3d(4, 5, 6));
  EXPECT_NO_THROW(w.finish());
  EXPECT_EQ(out, (std::vector<float>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(blocks[0].size, 6);
  EXPECT_EQ(blocks[0].field("defend").offset, 3);
}

// The client's lookup refuses what does not add up, and names what there is.
TEST(TaskFields, TheClientsLookupRefusesALayoutThatDoesNotAddUpAndNamesTheFields) {
  EXPECT_THROW(client::ObservationLayout({"ball"}, {9}, {2}, {"position", "velocity"}, {3, 3}),
               std::invalid_argument);
  EXPECT_THROW(client::ObservationLayout({"ball"}, {6}, {2}, {"position"}, {3}),
               std::invalid_argument);
  EXPECT_THROW(client::ObservationLayout({"ball"}, {6}, {1}, {"position", "velocity"}, {3, 3}),
               std::invalid_argument);
  const client::ObservationLayout l({"self", "ball"}, {4, 6}, {0, 2}, {"position", "velocity"},
                                    {3, 3});
  EXPECT_EQ(l.offset("ball", "velocity"), 7);
  EXPECT_EQ(l.size("ball", "velocity"), 3);
  EXPECT_TRUE(l.has("ball", "position"));
  EXPECT_FALSE(l.has("ball", "spin"));
  try {
    l.offset("ball", "spin");
    FAIL() << "an unknown field accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("position, velocity"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace olympics::sports
