// A field-event match in process for tests, the athletes standing still (zero targets) unless a
// test moves them by hand: stepping, waiting for a call, launching a humanoid.
#pragma once

#include <ode/ode.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "core/humanoid.h"
#include "registry.h"

namespace olympics::sports::athletics {

template <typename Match, typename Sport>
struct FieldEventSession {
  std::unique_ptr<Match> match;
  std::vector<float> zero;

  // A match of `sport` built as its sport builds it, kept as its own type for the tests.
  FieldEventSession(const std::string& sport_name, const std::string& mode,
                    const nlohmann::json& options) {
    const auto& sport = dynamic_cast<const Sport&>(sport_or_throw(sport_name));
    MatchSettings s;
    s.mode = mode;
    s.seed = 7;
    s.time_limit_s = 30;
    s.options = options;
    match = std::make_unique<Match>(sport.rules(options), sport.modes().at(mode),
                                    sport.layout(mode), s);
    zero.assign(match->action_size(), 0.0f);
  }

  void step() {
    std::vector<std::span<const float>> actions(match->slot_count(), zero);
    match->step(actions);
  }

  // The first event with this call, stepping until it comes (null after `ticks` or the end).
  nlohmann::json wait_for(const std::string& call, int ticks) {
    for (int i = 0; i < ticks && !match->outcome().match_over; ++i) {
      step();
      for (const auto& e : match->outcome().info["events"])
        if (e["call"] == call) return e;
    }
    return nullptr;
  }
};

// Every body of the humanoid moving at `v` (a scripted launch).
inline void give_velocity(core::Humanoid& h, const Eigen::Vector3d& v) {
  for (int b = 0; b < h.body_count(); ++b) dBodySetLinearVel(h.ode_body(b), v.x(), v.y(), v.z());
}

}  // namespace olympics::sports::athletics
