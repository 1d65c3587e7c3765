// Fencing and boxing as whole matches in process, played by their scripted baselines and bots:
// touches and punches land only where the rules allow, at the physics rate; off the piste both
// fencers go back to their lines; knock-downs, knock-outs and rounds happen as the referee says.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/control_rate.h"
#include "policies.h"
#include "registry.h"

namespace olympics::sports {
namespace {

struct Played {
  std::unique_ptr<SportMatch> match;
  std::vector<nlohmann::json> events;
  // The first observation after each referee call, per slot, by the call's index in `events`.
  std::vector<std::vector<std::vector<float>>> after;
};

Played play(const std::string& sport, const std::string& p0, const std::string& p1,
            std::uint64_t seed, double seconds, const nlohmann::json& options = {}) {
  Played out;
  out.match = sport_or_throw(sport).create({"1v1", seed, seconds, options});
  SportMatch& m = *out.match;
  std::vector<std::unique_ptr<client::Policy>> policies;
  for (int s = 0; s < 2; ++s) {
    policies.push_back(client::make_policy(s == 0 ? p0 : p1, seed + s));
    policies.back()->start({sport, "1v1", core::kControlDt,
                            client::ObservationLayout::from_blocks(m.layout().observation),
                            m.action_size()});
  }
  std::vector<std::vector<float>> obs(2, std::vector<float>(m.obs_size())),
      act(2, std::vector<float>(m.action_size()));
  while (!m.outcome().match_over) {
    for (int s = 0; s < 2; ++s) m.observe(s, obs[s]);
    for (size_t k = out.after.size(); k < out.events.size(); ++k) out.after.push_back(obs);
    for (int s = 0; s < 2; ++s) policies[s]->act(obs[s], act[s]);
    m.step({act[0], act[1]});
    for (const auto& e : m.outcome().info["events"]) out.events.push_back(e);
  }
  return out;
}

int block_offset(const SportMatch& m, const std::string& name) {
  return client::ObservationLayout::from_blocks(m.layout().observation).offset(name);
}

const std::set<std::string> kTargets = {"Pelvis", "Torso", "Spine", "Chest", "Head"};

TEST(FencingBout, ScriptedFencersScoreTouchesOnTargetsAtThePhysicsRate) {
  int touches = 0, hits = 0, off_tick_hits = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const Played p = play("fencing", "scripted", "scripted", seed, 180);
    EXPECT_EQ(p.match->outcome().reason, "bout_won");
    std::vector<double> last_hit = {-1, -1};
    for (const auto& e : p.events) {
      if (e["call"] == "hit") {
        ++hits;
        EXPECT_TRUE(kTargets.count(e["body"])) << e.dump();
        EXPECT_GE(e["force_n"].get<double>(), 50.0) << e.dump();
        EXPECT_NE(e["slot"], e["target_slot"]);
        const double t = e["t"];
        last_hit[e["slot"].get<int>()] = t;
        if (std::abs(t * core::kControlHz - std::round(t * core::kControlHz)) > 0.1)
          ++off_tick_hits;  // between two ticks: found at a physics step
      }
      if (e["call"] == "point" && (e["reason"] == "touch" || e["reason"] == "double")) {
        ++touches;
        EXPECT_GE(last_hit[e["slot"].get<int>()], 0) << "a touch scores only after a hit";
        EXPECT_LE(e["t"].get<double>() - last_hit[e["slot"].get<int>()], 0.1) << e.dump();
      }
    }
  }
  std::printf("3 bouts: %d hits, %d touches scored, %d hits between ticks\n", hits, touches,
              off_tick_hits);
  EXPECT_GE(touches, 5) << "the scripted fencers touch for real";
  EXPECT_GT(off_tick_hits, 0);
}

TEST(FencingBout, OffThePisteBothFencersGoBackToTheirLines) {
  int halts = 0;
  for (std::uint64_t seed = 1; seed <= 2; ++seed) {
    const Played p = play("fencing", "scripted", "scripted", seed, 60, {{"piste_width", 1.0}});
    const int piste = block_offset(*p.match, "piste");
    for (size_t k = 0; k < p.events.size(); ++k) {
      const auto& e = p.events[k];
      if (e["call"] != "halt" || e["reason"] != "off_piste" || k >= p.after.size()) continue;
      ++halts;
      EXPECT_EQ(p.events[k].value("culprit_slot", -2) >= -1, true);
      for (int s = 0; s < 2; ++s) {
        // "piste" starts with the root's position along the piste from its side: its line is
        // at -2 m, the seed moves it by up to 0.1 m.
        EXPECT_NEAR(p.after[k][s][piste], -2.0, 0.11) << "slot " << s << " after " << e.dump();
        EXPECT_NEAR(p.after[k][s][piste + 1], 0.0, 0.11);
      }
    }
  }
  EXPECT_GT(halts, 0) << "on a 1 m piste the fencers step off";
}

TEST(BoxingBout, AZeroBoxerGoesDownAndIsCountedOut) {
  const Played p = play("boxing", "scripted", "zero", 2, 60);
  const auto& o = p.match->outcome();
  ASSERT_EQ(o.reason, "knockout") << o.info.dump();
  double down_at = -1, out_at = -1;
  int out_slot = -1;
  for (const auto& e : p.events) {
    if (e["call"] == "knockdown" && e["slot"] == 1 && down_at < 0) down_at = e["t"];
    if (e["call"] == "knockout") out_at = e["t"], out_slot = e["slot"];
  }
  ASSERT_GE(down_at, 0);
  EXPECT_GE(out_at - down_at, 10.0 - 1e-9) << "the count is 10 s";
  EXPECT_EQ(o.winner_team, 1 - out_slot);
}

TEST(BoxingBout, RoundsEndWithCardsAndStartInTheCorners) {
  const Played p =
      play("boxing", "scripted", "scripted", 1, 60, {{"rounds", 2}, {"round_s", 5}, {"rest_s", 1}});
  const auto& o = p.match->outcome();
  EXPECT_TRUE(o.reason == "decision" || o.reason == "decision_draw" || o.reason == "knockout");
  const int ring = block_offset(*p.match, "ring");
  int ends = 0, starts = 0, punches = 0;
  for (size_t k = 0; k < p.events.size(); ++k) {
    const auto& e = p.events[k];
    if (e["call"] == "punch") {
      ++punches;
      EXPECT_TRUE(kTargets.count(e["body"])) << e.dump();
      EXPECT_GE(e["force_n"].get<double>(), 100.0) << e.dump();
    }
    if (e["call"] == "round_end") {
      ++ends;
      const int a = e["card_0"], b = e["card_1"];
      EXPECT_TRUE(a == 10 || b == 10 || (a < 10 && b < 10)) << e.dump();
    }
    if (e["call"] != "round_start" && e["call"] != "round_end") continue;
    starts += e["call"] == "round_start";
    if (k >= p.after.size()) continue;
    for (int s = 0; s < 2; ++s)  // in its corner: x = -1 m from its side, jittered 0.1 m
      EXPECT_NEAR(p.after[k][s][ring], -1.0, 0.11) << "slot " << s << " after " << e.dump();
  }
  if (o.reason != "knockout") {
    EXPECT_EQ(ends, 2);
    EXPECT_EQ(starts, 1);
    ASSERT_EQ(o.info["rounds"].size(), 2u);
    int total0 = 0, total1 = 0;
    for (const auto& r : o.info["rounds"])
      total0 += r["card"][0].get<int>(), total1 += r["card"][1].get<int>();
    EXPECT_EQ(o.scores[0], total0);
    EXPECT_EQ(o.scores[1], total1);
  }
  std::printf("%s after %d punches, cards %g-%g\n", o.reason.c_str(), punches, o.scores[0],
              o.scores[1]);
}

}  // namespace
}  // namespace olympics::sports
