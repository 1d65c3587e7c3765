// The observation's named fields travel with each match: a client builds its layout from what a
// real server sent (match_created_t, protocol 6), and finds in it, by name, the blocks and fields
// the sport declares, and there the values the sport wrote.
#include "framework/heading_frame.h"
#include "match_client.h"
#include "observation_layout.h"
#include "registry.h"
#include "server_fixture.h"
#include "soccer/soccer_match.h"

namespace olympics::testing {
namespace {

TEST(ObservationFields, AClientReadsByNameFromTheServersDescriptionWhatTheSportWrote) {
  ServerFixture server;
  client::ClientOptions o;
  o.lcm_url = server.url();
  client::MatchClient c(o);
  client::MatchRequest req;
  req.sport = "soccer";
  req.mode = "2v2";
  req.seed = 9;
  req.time_limit_s = 1.0;
  req.request_id = "fields";
  const auto created = c.request_match(req, 60);
  c.join(created.match_id, {0, 1, 2, 3}, 60);
  const auto layout = client::ObservationLayout::from_message(c.match());

  // The same match in process: the same seed gives the same first observation.
  auto match = sports::sport_or_throw("soccer").create({"2v2", 9, 1.0, {}});
  const auto declared = client::ObservationLayout::from_blocks(match->layout().observation);
  ASSERT_EQ(layout.blocks().size(), declared.blocks().size());
  for (size_t b = 0; b < layout.blocks().size(); ++b) {
    const auto &sent = layout.blocks()[b], &mine = declared.blocks()[b];
    EXPECT_EQ(sent.name, mine.name);
    EXPECT_EQ(sent.offset, mine.offset) << sent.name;
    ASSERT_EQ(sent.fields.size(), mine.fields.size()) << sent.name;
    ASSERT_FALSE(sent.fields.empty()) << sent.name;
    for (size_t f = 0; f < sent.fields.size(); ++f) {
      EXPECT_EQ(sent.fields[f].name, mine.fields[f].name) << sent.name;
      EXPECT_EQ(sent.fields[f].offset, mine.fields[f].offset) << sent.name;
      EXPECT_EQ(sent.fields[f].size, mine.fields[f].size) << sent.name;
    }
  }

  const auto first = c.next(60);
  ASSERT_TRUE(first);
  ASSERT_EQ(first->slots, (std::vector<int>{0, 1, 2, 3}));
  const auto& soccer = dynamic_cast<const sports::soccer::SoccerMatch&>(*match);
  for (int slot = 0; slot < 4; ++slot) {
    std::vector<float> expected(match->obs_size());
    match->observe(slot, expected);
    EXPECT_EQ(first->obs[slot], expected) << "slot " << slot;
    // The ball's position field holds the ball's position, seen from the slot's root.
    const sports::HeadingFrame frame(soccer.scene().humanoid(slot).body_state(0));
    const Eigen::Vector3d ball = frame.point(soccer.ball().position());
    const int at = layout.offset("ball", "position");
    ASSERT_EQ(layout.size("ball", "position"), 3);
    for (int i = 0; i < 3; ++i) EXPECT_FLOAT_EQ(first->obs[slot][at + i], ball[i]) << slot;
    EXPECT_EQ(first->obs[slot][layout.offset("match", "time_left")], 1.0f);
  }

  // Played out with zero actions, so the server is left with nothing running.
  std::vector<std::vector<float>> zero(4, std::vector<float>(created.action_size, 0.0f));
  int tick = first->tick;
  c.act(tick, zero);
  while (auto obs = c.next(60)) {
    if (obs->all_done()) break;
    c.act(obs->tick, zero);
  }
  c.wait_result(60);
}

}  // namespace
}  // namespace olympics::testing
